// The glTF reader: Skins (joints and inverse bind matrices), morph targets and node animations (samplers
// and channels), each bounded and checked; a bad one is refused by name and the mesh drawn at
// rest.
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

// The file's animations: each checked whole, and one that breaks a rule refused with a
// warning naming it and the rule (the scene stays, static where it would have moved).
void GltfReader::readAnimations() {
  for (std::size_t i = 0; i < m_.animations.size(); ++i) {
    const tinygltf::Animation& a = m_.animations[i];
    const std::string label = "animation " + std::to_string(i) + (a.name.empty() ? std::string() : " '" + printable(a.name) + "'");
    Result<SceneAnimation> read = readAnimation(a);
    if (!read) {
      warn_.add(name_ + ": " + label + " is not played: " + read.error());
      continue;
    }
    read->name = a.name.empty() ? "animation " + std::to_string(i + 1) : printable(a.name);
    animations_.push_back(std::move(*read));
  }
}

// Whether skin `k` can be read at all (its joints exist); readSkins checks the rest.
bool GltfReader::skinUsable(int k) const {
  const tinygltf::Skin& skin = m_.skins[static_cast<std::size_t>(k)];
  if (skin.joints.empty() || skin.joints.size() > kMaxJoints) return false;
  return std::all_of(skin.joints.begin(), skin.joints.end(), [&](int j) { return j >= 0 && j < static_cast<int>(m_.nodes.size()); });
}

// The skins the scene's objects use, each checked whole; a refused one is named and its
// objects drawn in their bind pose.
void GltfReader::readSkins() {
  std::set<int> used;
  for (const Object& o : objects_)
    if (o.skin >= 0) used.insert(o.skin);
  for (std::size_t k = 0; k < m_.skins.size(); ++k) {
    const tinygltf::Skin& g = m_.skins[k];
    const std::string label = "skin " + std::to_string(k) + (g.name.empty() ? std::string() : " '" + printable(g.name) + "'");
    if (!skinUsable(static_cast<int>(k))) {
      warn_.add(name_ + ": " + label + " is not applied: " +
                (g.joints.empty() ? std::string("it has no joints")
                 : g.joints.size() > kMaxJoints ? "it has more than " + std::to_string(kMaxJoints) + " joints"
                                                : std::string("a joint names a node that does not exist")));
      continue;
    }
    if (!used.count(static_cast<int>(k))) continue;
    Result<SceneSkin> read = readSkin(g);
    if (!read) {
      warn_.add(name_ + ": " + label + " is not applied: " + read.error() + "; its meshes are drawn in their bind pose");
      continue;
    }
    read->name = g.name.empty() ? "skin " + std::to_string(k + 1) : printable(g.name);
    skinOf_[static_cast<int>(k)] = static_cast<int>(skins_.size());
    skins_.push_back(std::move(*read));
  }
}

Result<SceneSkin> GltfReader::readSkin(const tinygltf::Skin& g) {
  SceneSkin out;
  for (int j : g.joints) {
    const auto node = nodeOf_.find(j);
    if (node == nodeOf_.end()) return Error{"its joint node " + std::to_string(j) + " is not in the scene"};
    out.joints.push_back(node->second);
  }
  // glTF: without inverse bind matrices every joint's is the identity.
  out.inverseBind.assign(g.joints.size(), glm::mat4(1.0f));
  if (g.inverseBindMatrices >= 0) {
    Result<AccessorView> ibm = accessor(g.inverseBindMatrices, "inverse bind matrices", {TINYGLTF_TYPE_MAT4});
    if (!ibm) return Error{ibm.error().rfind(name_ + ": ", 0) == 0 ? ibm.error().substr(name_.size() + 2) : ibm.error()};
    if (ibm->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return Error{"its inverse bind matrices are not floats"};
    if (ibm->count < g.joints.size())
      return Error{"it has " + std::to_string(g.joints.size()) + " joints but " + std::to_string(ibm->count) + " inverse bind matrices"};
    for (std::size_t j = 0; j < g.joints.size(); ++j)
      for (int c = 0; c < 16; ++c) {
        const double v = ibm->component(j, c);
        if (!std::isfinite(v)) return Error{"inverse bind matrix " + std::to_string(j) + " is not finite"};
        out.inverseBind[j][c / 4][c % 4] = static_cast<float>(v);
      }
  }
  return out;
}

Result<SceneAnimation> GltfReader::readAnimation(const tinygltf::Animation& a) {
  SceneAnimation out;
  if (a.channels.empty()) return Error{"it has no channels"};
  bool first = true;
  for (std::size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = a.channels[c];
    const std::string where = "channel " + std::to_string(c);
    AnimationChannel channel;
    if (ch.target_path == "weights") channel.property = AnimatedProperty::Weights;
    else if (ch.target_path == "translation") channel.property = AnimatedProperty::Translation;
    else if (ch.target_path == "rotation") channel.property = AnimatedProperty::Rotation;
    else if (ch.target_path == "scale") channel.property = AnimatedProperty::Scale;
    else return Error{where + " animates '" + printable(ch.target_path, 40) + "' (translation, rotation, scale or weights are glTF's)"};
    if (ch.target_node < 0 || ch.target_node >= static_cast<int>(m_.nodes.size()))
      return Error{where + " names node " + std::to_string(ch.target_node) + ", which does not exist"};
    const auto node = nodeOf_.find(ch.target_node);
    if (node == nodeOf_.end()) continue;  // a node outside the default scene: nothing drawn moves
    if (nodes_[static_cast<std::size_t>(node->second)].matrix)
      return Error{where + " animates node " + std::to_string(ch.target_node) + ", which is given by a matrix (glTF allows animating only TRS nodes)"};
    channel.node = node->second;
    const bool weights = channel.property == AnimatedProperty::Weights;
    const std::size_t targets = nodes_[static_cast<std::size_t>(node->second)].weights.size();
    if (weights && targets == 0) return Error{where + " animates the morph weights of node " + std::to_string(ch.target_node) + ", whose mesh has no morph targets"};
    channel.width = weights ? static_cast<int>(targets) : channel.property == AnimatedProperty::Rotation ? 4 : 3;
    if (ch.sampler < 0 || ch.sampler >= static_cast<int>(a.samplers.size()))
      return Error{where + " names sampler " + std::to_string(ch.sampler) + ", which does not exist"};
    const tinygltf::AnimationSampler& sampler = a.samplers[static_cast<std::size_t>(ch.sampler)];
    if (sampler.interpolation == "STEP") channel.interpolation = Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE") channel.interpolation = Interpolation::CubicSpline;
    else if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty()) channel.interpolation = Interpolation::Linear;
    else return Error{where + ": interpolation '" + printable(sampler.interpolation, 40) + "' is not STEP, LINEAR or CUBICSPLINE"};
    // The accessor's message without the file's name, which the warning gives once.
    const auto unnamed = [&](const std::string& e) { return Error{e.rfind(name_ + ": ", 0) == 0 ? e.substr(name_.size() + 2) : e}; };
    Result<AccessorView> input = accessor(sampler.input, where + "'s keyframe times", {TINYGLTF_TYPE_SCALAR});
    if (!input) return unnamed(input.error());
    if (input->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return Error{where + "'s keyframe times are not floats"};
    if (input->count == 0) return Error{where + " has no keyframes"};
    const bool rotation = channel.property == AnimatedProperty::Rotation;
    Result<AccessorView> output = accessor(sampler.output, where + "'s values",
                                           {weights ? TINYGLTF_TYPE_SCALAR : rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3});
    if (!output) return unnamed(output.error());
    // Weights: one scalar per morph target per value.
    const std::size_t perKey = (channel.interpolation == Interpolation::CubicSpline ? 3 : 1) * (weights ? targets : 1);
    if (output->count != input->count * perKey)
      return Error{where + " has " + std::to_string(input->count) + " keyframe times but " + std::to_string(output->count) + " values (" +
                   (channel.interpolation == Interpolation::CubicSpline ? "a cubic spline needs three per time" : "one per time") +
                   (weights ? ", times " + std::to_string(targets) + " morph targets" : std::string()) + ")"};
    // Channels copy their sampler's keys: bounded over the file, however often one is shared.
    animationKeys_ += output->count;
    if (animationKeys_ > kMaxAnimationKeys) return Error{"the file's animations hold more than " + std::to_string(kMaxAnimationKeys) + " keyframe values"};
    channel.times.resize(input->count);
    for (std::size_t k = 0; k < input->count; ++k) {
      const double t = input->component(k, 0);
      if (!std::isfinite(t)) return Error{where + ": keyframe time " + std::to_string(k) + " is not finite"};
      channel.times[k] = static_cast<float>(t);
      if (k > 0 && !(channel.times[k] > channel.times[k - 1]))
        return Error{where + ": keyframe times do not increase (time " + std::to_string(k) + " is " + json::number(t) + " after " +
                     json::number(channel.times[k - 1]) + ")"};
    }
    channel.values.resize(output->count * static_cast<std::size_t>(output->components));
    for (std::size_t k = 0; k < output->count; ++k)
      for (int j = 0; j < output->components; ++j) {
        const double x = output->component(k, j);
        if (!std::isfinite(x)) return Error{where + ": value " + std::to_string(k) + " is not finite"};
        channel.values[k * static_cast<std::size_t>(output->components) + static_cast<std::size_t>(j)] = static_cast<float>(x);
      }
    if (rotation && channel.interpolation != Interpolation::CubicSpline)
      for (std::size_t k = 0; k < output->count; ++k) {
        const float* q = &channel.values[4 * k];
        if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 1e-12f)) return Error{where + ": a rotation is the zero quaternion"};
      }
    out.start = first ? channel.times.front() : std::min(out.start, channel.times.front());
    out.end = first ? channel.times.back() : std::max(out.end, channel.times.back());
    first = false;
    out.channels.push_back(std::move(channel));
  }
  if (out.channels.empty()) return Error{"it moves nothing this viewer draws (its channels drive nodes outside the scene)"};
  return out;
}

// The primitive's skin weights and morph targets into the soup's per-vertex deformation
// (zero where absent: the vertex stays at rest). Bad data does not fail the file: the first
// problem is kept (Target::deformProblem) and the mesh is drawn at rest, named.
void GltfReader::readDeformation(const tinygltf::Primitive& prim, const glm::dmat3& placement, std::size_t count, const std::string& where, Target& t) {
  PolygonSoup& soup = t.soup;
  const std::size_t width = soup.deformWidth();
  const std::size_t first = soup.deform.size() / width;
  soup.deform.resize((first + count) * width, 0.0f);
  const auto problem = [&](const std::string& what) {
    if (t.deformProblem.empty()) t.deformProblem = where + ": " + what;
  };
  const auto unnamed = [&](const std::string& e) { return e.rfind(name_ + ": ", 0) == 0 ? e.substr(name_.size() + 2) : e; };
  if (soup.skinned) {
    const std::size_t joints = m_.skins[static_cast<std::size_t>(t.skin)].joints.size();
    const auto j = prim.attributes.find("JOINTS_0"), w = prim.attributes.find("WEIGHTS_0");
    if (j == prim.attributes.end() || w == prim.attributes.end()) {
      problem("a skinned primitive without JOINTS_0 and WEIGHTS_0");
    } else {
      Result<AccessorView> ja = accessor(j->second, where + " JOINTS_0", {TINYGLTF_TYPE_VEC4});
      Result<AccessorView> wa = accessor(w->second, where + " WEIGHTS_0", {TINYGLTF_TYPE_VEC4});
      if (!ja) return problem(unnamed(ja.error()));
      if (!wa) return problem(unnamed(wa.error()));
      if (ja->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ja->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
        return problem("JOINTS_0 must be unsigned bytes or shorts");
      if (ja->count != count || wa->count != count)
        return problem("JOINTS_0 and WEIGHTS_0 have " + std::to_string(ja->count) + " and " + std::to_string(wa->count) + " elements for " +
                       std::to_string(count) + " positions");
      std::size_t renormalised = 0;
      for (std::size_t i = 0; i < count; ++i) {
        float* v = &soup.deform[(first + i) * width];
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
          const double weight = wa->component(i, k);
          if (!std::isfinite(weight) || weight < 0.0) return problem("vertex " + std::to_string(i) + " has a weight that is negative or not finite");
          const std::uint64_t joint = static_cast<std::uint64_t>(ja->component(i, k));
          if (weight > 0.0 && joint >= joints)
            return problem("vertex " + std::to_string(i) + " names joint " + std::to_string(joint) + ", past the skin's " + std::to_string(joints));
          v[k] = weight > 0.0 ? static_cast<float>(joint) : 0.0f;
          v[4 + k] = static_cast<float>(weight);
          sum += v[4 + k];
        }
        // glTF says the weights sum to one; a small drift (quantised weights) is normalised,
        // a vertex with none stays at rest.
        if (sum > 0.0f && std::abs(sum - 1.0f) > 1e-3f) {
          if (std::abs(sum - 1.0f) > 0.01f) ++renormalised;
          for (int k = 0; k < 4; ++k) v[4 + k] /= sum;
        }
      }
      if (renormalised > 0)
        warn_.add(name_ + ": " + where + ": " + std::to_string(renormalised) + " vertices' skin weights do not sum to one; normalised");
      if (prim.attributes.count("JOINTS_1")) warn_.add(name_ + ": " + where + ": only the first four joint influences per vertex are read");
    }
  }
  if (soup.morphTargets == 0) return;
  if (prim.targets.size() != soup.morphTargets)
    return problem("it has " + std::to_string(prim.targets.size()) + " morph targets where its mesh's first primitive has " +
                   std::to_string(soup.morphTargets));
  const std::size_t base = soup.skinned ? 8 : 0;
  for (std::size_t k = 0; k < soup.morphTargets; ++k)
    for (const char* attribute : {"POSITION", "NORMAL"}) {
      const auto a = prim.targets[k].find(attribute);
      if (a == prim.targets[k].end()) continue;
      Result<AccessorView> deltas = accessor(a->second, where + " morph target " + std::to_string(k) + " " + attribute, {TINYGLTF_TYPE_VEC3});
      if (!deltas) return problem(unnamed(deltas.error()));
      if (deltas->count != count)
        return problem("morph target " + std::to_string(k) + " " + attribute + " has " + std::to_string(deltas->count) + " elements for " +
                       std::to_string(count) + " positions");
      const std::size_t at = base + 6 * k + (attribute[0] == 'N' ? 3 : 0);
      for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 d = placement * glm::dvec3(deltas->component(i, 0), deltas->component(i, 1), deltas->component(i, 2));
        if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z))
          return problem("morph target " + std::to_string(k) + " " + attribute + " " + std::to_string(i) + " is not finite");
        float* v = &soup.deform[(first + i) * width + at];
        v[0] = static_cast<float>(d.x), v[1] = static_cast<float>(d.y), v[2] = static_cast<float>(d.z);
      }
    }
}

}  // namespace npr::gltf
