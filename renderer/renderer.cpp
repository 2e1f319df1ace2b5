// The render paths (see renderer.h).
//
// [SECTION] Pass states: every pass's fixed-function state in one visible place
// [SECTION] Resources: mesh, palette and lookup-table uploads
// [SECTION] Per-triangle shading cache
// [SECTION] Frame: background, single-pass paths, the stencil path
#include "renderer/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lines/feature_edges.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/gl_program.h"
#include "renderer/lighting/lighting_uniforms.h"

namespace npr {

// ---------------------------------------------------------------------------------------
// [SECTION] Pass states
namespace {

struct PassState {
  bool depthTest = false, depthWrite = false, colorWrite = true, blend = false, stencilTest = false, scissor = false;
  GLenum stencilFunc = GL_ALWAYS;
  GLenum stencilPass = GL_KEEP;  // op when stencil and depth pass
};

// Background of every path: behind everything, touches no depth.
constexpr PassState kBackgroundPass{};
// Single-pass paths: ordinary depth-tested drawing.
constexpr PassState kMeshPass{true, true, true, false, false, false, GL_ALWAYS, GL_KEEP};
// Stencil path, per bucket: (1) the bucket's triangles mark visible pixels in the stencil,
constexpr PassState kStencilMask{true, true, false, false, true, false, GL_ALWAYS, GL_REPLACE};
// (2) the background where marked, (3) the palette layer blended over it, clearing the mark.
constexpr PassState kStencilBackground{false, false, true, false, true, true, GL_EQUAL, GL_KEEP};
constexpr PassState kStencilLayer{false, false, true, true, true, true, GL_EQUAL, GL_ZERO};

void apply(const PassState& s) {
  s.depthTest ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
  const GLboolean c = s.colorWrite ? GL_TRUE : GL_FALSE;
  glColorMask(c, c, c, c);
  if (s.blend) {
    glEnable(GL_BLEND);
    // Colour blends; destination alpha stays as it is (opaque), so read-backs and screenshots stay opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  } else {
    glDisable(GL_BLEND);
  }
  if (s.stencilTest) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(s.stencilFunc, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, s.stencilPass);
    glStencilMask(0xFF);
  } else {
    glDisable(GL_STENCIL_TEST);
  }
  s.scissor ? glEnable(GL_SCISSOR_TEST) : glDisable(GL_SCISSOR_TEST);
}

// Leaves the context as an overlay drawn after us expects it.
void restoreDefaults() {
  apply(kBackgroundPass);
  glDisable(GL_SCISSOR_TEST);
  glStencilMask(0xFF);
  glBindVertexArray(0);
  glUseProgram(0);
}

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool nearlyEqual(float a, float b) { return std::fabs(a - b) <= 1e-5f * std::max(1.0f, std::max(std::fabs(a), std::fabs(b))); }
bool nearlyEqual(const glm::vec3& a, const glm::vec3& b) { return nearlyEqual(a.x, b.x) && nearlyEqual(a.y, b.y) && nearlyEqual(a.z, b.z); }

// Whether per-triangle results can differ between two preparations of the lighting (in the
// same space). The eye matters only to specular and two-sided terms.
bool sameLighting(const PreparedLighting<float>& a, const PreparedLighting<float>& b) {
  if (a.count != b.count || a.lighting != b.lighting || a.specular != b.specular || a.localViewer != b.localViewer ||
      a.twoSided != b.twoSided || a.tone != b.tone)
    return false;
  if (a.tone != ToneModel::OpenGL)
    for (int s = 0; s < 2; ++s)
      if (!nearlyEqual(a.cool[s], b.cool[s]) || !nearlyEqual(a.warm[s], b.warm[s]) || a.splashAlpha != b.splashAlpha ||
          a.splashPower != b.splashPower)
        return false;
  for (int s = 0; s < 2; ++s)
    if (!nearlyEqual(a.base[s], b.base[s]) || a.shininess[s] != b.shininess[s]) return false;
  if (a.specular || a.twoSided)
    if (!nearlyEqual(a.eye, b.eye) || !nearlyEqual(a.viewDirection, b.viewDirection)) return false;
  for (int i = 0; i < a.count; ++i) {
    const auto &x = a.lights[i], &y = b.lights[i];
    for (int s = 0; s < 2; ++s)
      if (!nearlyEqual(x.ambient[s], y.ambient[s]) || !nearlyEqual(x.diffuse[s], y.diffuse[s]) ||
          !nearlyEqual(x.specular[s], y.specular[s]))
        return false;
    if (x.positional != y.positional || !nearlyEqual(x.position, y.position) || x.spot != y.spot || x.k0 != y.k0 ||
        x.k1 != y.k1 || x.k2 != y.k2)
      return false;
    // A light's spot direction matters only when it is a spotlight.
    if (x.spot && (!nearlyEqual(x.spotDirection, y.spotDirection) || x.spotExponent != y.spotExponent ||
                   x.spotCosCutoff != y.spotCosCutoff))
      return false;
  }
  return true;
}

enum TextureUnit { kUnitPalette = 0, kUnitBackground, kUnitLutIndex, kUnitLutBlend, kUnitLut3D };

}  // namespace

struct Renderer::GpuPalette {
  gl::Texture layers;      // GL_TEXTURE_2D_ARRAY, RGBA8, one layer per entry
  gl::Texture background;  // GL_TEXTURE_2D, only for an image background
  std::vector<glm::ivec2> layerSizes;
  bool sizesDiffer = false;
  bool precomposited = false;
  glm::vec3 backgroundColour{1.0f};
  glm::ivec2 backgroundSize{1, 1};
  bool backgroundImage = false;
};

Result<std::unique_ptr<Renderer>> Renderer::create() {
  if (epoxy_gl_version() < 33) return Error{"the renderer needs OpenGL 3.3 or later; this context is " + std::to_string(epoxy_gl_version())};
  std::unique_ptr<Renderer> r(new Renderer());
  r->emptyVao_ = gl::createVertexArray();
  for (auto& q : r->timers_) q = gl::createQuery();
  return r;
}

Renderer::~Renderer() = default;

// ---------------------------------------------------------------------------------------
// [SECTION] Resources

namespace {
gl::Buffer uploadBuffer(GLenum target, const void* data, std::size_t bytes, GLenum usage) {
  gl::Buffer b = gl::createBuffer();
  glBindBuffer(target, b.id());
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
  return b;
}
}  // namespace

void Renderer::setMesh(const Mesh* mesh) {
  mesh_ = mesh;
  ++meshGeneration_;
  shadingKey_.valid = false;
  edges_.reset();
  uploadedCreaseAngle_ = -1.0f;
  silhouetteEye_ = glm::vec3(NAN);
  staticLineCount_ = silhouetteCount_ = 0;
  vao_.reset();
  positions_.reset();
  normals_.reset();
  indices_.reset();
  bucketIndices_.reset();
  triangleCount_ = 0;
  if (!mesh || mesh->indices.empty()) return;
  triangleCount_ = mesh->triangleCount();
  vao_ = gl::createVertexArray();
  glBindVertexArray(vao_.id());
  positions_ = uploadBuffer(GL_ARRAY_BUFFER, mesh->positions.data(), mesh->positions.size() * sizeof(glm::vec3), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  normals_ = uploadBuffer(GL_ARRAY_BUFFER, mesh->normals.data(), mesh->normals.size() * sizeof(glm::vec3), GL_STATIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  indices_ = uploadBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->indices.data(), mesh->indices.size() * sizeof(std::uint32_t), GL_STATIC_DRAW);
  glBindVertexArray(0);
  bucketIndices_ = gl::createBuffer();
  stats_.bufferUploads += 3;
}

Status Renderer::setPalette(const Palette& p) {
  const int n = static_cast<int>(p.entries.size());
  if (n < 1 || n > kMaxPaletteEntries) return Error{"palette must have 1.." + std::to_string(kMaxPaletteEntries) + " entries"};
  GLint maxLayers = 0, maxSize = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (n > maxLayers) return Error{"palette has " + std::to_string(n) + " entries; this GPU holds " + std::to_string(maxLayers) + " layers"};
  auto gp = std::make_unique<GpuPalette>();
  int w = 1, h = 1;
  for (const auto& e : p.entries) {
    w = std::max(w, e.image.width);
    h = std::max(h, e.image.height);
    gp->layerSizes.push_back({e.image.width, e.image.height});
    gp->sizesDiffer |= gp->layerSizes.back() != gp->layerSizes.front();
  }
  if (w > maxSize || h > maxSize) return Error{"palette texture " + std::to_string(w) + "x" + std::to_string(h) + " exceeds this GPU's limit " + std::to_string(maxSize)};
  const RgbaImage* bg = p.backgroundImage ? &*p.backgroundImage : nullptr;
  // Precompositing each layer over the background is exact when the background is a solid
  // colour or an image the size of every layer (both tile from the same screen corner).
  gp->precomposited = !bg || (!gp->sizesDiffer && bg->width == w && bg->height == h);
  gp->backgroundColour = p.backgroundColour;
  gp->layers = gl::createTexture();
  glActiveTexture(GL_TEXTURE0 + kUnitPalette);
  glBindTexture(GL_TEXTURE_2D_ARRAY, gp->layers.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, w, h, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> flipped;
  auto flipRows = [&](const RgbaImage& img) {
    // Images are stored top row first; GL's rows start at the bottom of the screen.
    const size_t row = static_cast<size_t>(img.width) * 4;
    flipped.resize(img.pixels.size());
    for (int y = 0; y < img.height; ++y)
      std::memcpy(&flipped[static_cast<size_t>(img.height - 1 - y) * row], &img.pixels[static_cast<size_t>(y) * row], row);
    return flipped.data();
  };
  for (int i = 0; i < n; ++i) {
    const RgbaImage& src = p.entries[static_cast<size_t>(i)].image;
    const RgbaImage img = gp->precomposited ? compositeOver(src, p.backgroundColour, bg) : src;
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, i, img.width, img.height, 1, GL_RGBA, GL_UNSIGNED_BYTE, flipRows(img));
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  if (bg) {
    gp->backgroundImage = true;
    gp->backgroundSize = {bg->width, bg->height};
    gp->background = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + kUnitBackground);
    glBindTexture(GL_TEXTURE_2D, gp->background.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, bg->width, bg->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipRows(*bg));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  if (glGetError() == GL_OUT_OF_MEMORY) return Error{"palette upload failed: out of GPU memory"};
  palette_ = std::move(gp);
  paletteSize_ = n;
  averages_ = p.averages();
  ++paletteGeneration_;
  stats_.bufferUploads += 1;
  return okStatus();
}

Status Renderer::ensureMatcher(const RenderSettings& s) {
  if (matcher_ && matcherKey_.palette == paletteGeneration_ && matcherKey_.mode == s.match && matcherKey_.scale == s.rangeScale &&
      matcherKey_.bands == s.bands)
    return okStatus();
  Result<PaletteMatcher> m = PaletteMatcher::create(averages_, s.match, s.rangeScale, s.bands);
  if (!m) return Error{m.error()};
  matcher_ = std::move(*m);
  matcherKey_ = {paletteGeneration_, s.match, s.rangeScale, s.bands};
  ++matcherGeneration_;
  ++stats_.lutBuilds;
  const int L = PaletteMatcher::kLut1DSize;
  glActiveTexture(GL_TEXTURE0 + kUnitLutIndex);
  if (s.match == MatchMode::Colors) {
    const int G = PaletteMatcher::kLut3DSize;
    const std::vector<std::uint8_t> lut = matcher_->buildLut3D();
    lut3D_ = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + kUnitLut3D);
    glBindTexture(GL_TEXTURE_3D, lut3D_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RG8UI, G, G, G, 0, GL_RG_INTEGER, GL_UNSIGNED_BYTE, lut.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
  } else {
    const std::vector<std::uint8_t> index = matcher_->buildLutIndex1D();
    const std::vector<float> blend = matcher_->buildLutBlend1D();
    lutIndex_ = gl::createTexture();
    glBindTexture(GL_TEXTURE_2D, lutIndex_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, L, 1, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, index.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    lutBlend_ = gl::createTexture();
    glActiveTexture(GL_TEXTURE0 + kUnitLutBlend);
    glBindTexture(GL_TEXTURE_2D, lutBlend_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, L, 1, 0, GL_RGBA, GL_FLOAT, blend.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  ++stats_.bufferUploads;
  return okStatus();
}

Result<GLuint> Renderer::program(const std::string& vertex, const std::string& fragment, std::vector<std::string> defines) {
  std::string key = vertex + "|" + fragment;
  for (const auto& d : defines) key += "|" + d;
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second.id();
  Result<gl::Program> p = gl::buildProgram(vertex, fragment, defines);
  if (!p) return Error{p.error()};
  ++stats_.shaderBuilds;
  const GLuint id = p->id();
  programs_.emplace(key, std::move(*p));
  return id;
}

std::vector<std::string> Renderer::paletteDefines(MatchMode mode) const {
  std::vector<std::string> d;
  d.push_back("PALETTE_SIZE " + std::to_string(paletteSize_));
  if (palette_->sizesDiffer) d.push_back("LAYER_SIZES_DIFFER");
  if (palette_->precomposited) d.push_back("PALETTE_PRECOMPOSITED");
  else if (palette_->backgroundImage) d.push_back("BACKGROUND_IMAGE");
  d.push_back(mode == MatchMode::Colors ? "MATCH_COLORS" : mode == MatchMode::Intensity ? "MATCH_INTENSITY" : "MATCH_ORDER");
  d.push_back("LUT1D_SIZE " + std::to_string(PaletteMatcher::kLut1DSize));
  d.push_back("LUT3D_SIZE " + std::to_string(PaletteMatcher::kLut3DSize));
  return d;
}

void Renderer::bindPaletteTextures(GLuint prog) const {
  glActiveTexture(GL_TEXTURE0 + kUnitPalette);
  glBindTexture(GL_TEXTURE_2D_ARRAY, palette_->layers.id());
  gl::setUniform(prog, "uPalette", int(kUnitPalette));
  if (palette_->sizesDiffer) gl::setUniformArray(prog, "uLayerSize", palette_->layerSizes.data(), paletteSize_);
  else gl::setUniform(prog, "uLayerSize0", palette_->layerSizes[0]);
  if (palette_->backgroundImage) {
    glActiveTexture(GL_TEXTURE0 + kUnitBackground);
    glBindTexture(GL_TEXTURE_2D, palette_->background.id());
    gl::setUniform(prog, "uBackground", int(kUnitBackground));
    gl::setUniform(prog, "uBackgroundSize", palette_->backgroundSize);
  }
  gl::setUniform(prog, "uBackgroundColour", palette_->backgroundColour);
  if (matcher_ && matcher_->mode() == MatchMode::Colors) {
    glActiveTexture(GL_TEXTURE0 + kUnitLut3D);
    glBindTexture(GL_TEXTURE_3D, lut3D_.id());
    gl::setUniform(prog, "uLut3D", int(kUnitLut3D));
    gl::setUniformArray(prog, "uAverages", matcher_->scaledAverages().data(), paletteSize_);
  } else {
    glActiveTexture(GL_TEXTURE0 + kUnitLutIndex);
    glBindTexture(GL_TEXTURE_2D, lutIndex_.id());
    gl::setUniform(prog, "uLutIndex", int(kUnitLutIndex));
    glActiveTexture(GL_TEXTURE0 + kUnitLutBlend);
    glBindTexture(GL_TEXTURE_2D, lutBlend_.id());
    gl::setUniform(prog, "uLutBlend", int(kUnitLutBlend));
  }
  glActiveTexture(GL_TEXTURE0);
}

// ---------------------------------------------------------------------------------------
// [SECTION] Per-triangle shading cache

void Renderer::ensureTriangleShading(const glm::mat4& modelView, const CameraMatrices& camera, const RenderSettings& s,
                                     const glm::ivec4& viewport) {
  const bool rigid = isRigid(modelView);
  PreparedLighting<float> prepared = prepareLighting<float>(lighting_, rigid ? glm::inverse(modelView) : glm::mat4(1.0f));
  const bool same = shadingKey_.valid && rigid && shadingKey_.mesh == meshGeneration_ &&
                    shadingKey_.matcher == matcherGeneration_ &&
                    sameLighting(shadingKey_.lighting, prepared);
  if (!same) {
    const auto t0 = std::chrono::steady_clock::now();
    TriangleShadingOptions opt;
    // Both per-triangle paths draw bucket by bucket: the triangle path sets the entry as a
    // uniform per bucket, because reading a per-triangle value by gl_PrimitiveID made llvmpipe
    // process the 871K-triangle mesh about 30% slower than the reference render.
    opt.buildBuckets = true;
    shadeTriangles(*mesh_, lighting_, modelView, *matcher_, opt, shading_);
    stats_.cpuShadingMs += msSince(t0);
    ++stats_.lightingRecomputes;
    shadingKey_ = {meshGeneration_, matcherGeneration_, prepared, /*valid=*/rigid};  // eye-space results are not reusable
    bucketsUploaded_ = false;
    boundsValid_ = false;
  }
  if (!bucketsUploaded_) {
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bucketIndices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(shading_.bucketIndices.size() * sizeof(std::uint32_t)),
                 shading_.bucketIndices.data(), GL_STREAM_DRAW);
    glBindVertexArray(0);
    bucketsUploaded_ = true;
    ++stats_.bufferUploads;
  }
  if (s.path == RenderPath::Stencil && s.stencilScissor) {
    const glm::mat4 mvp = camera.projection * modelView;
    const glm::ivec2 size(viewport.z, viewport.w);
    if (mvp != projectedViewProjection_ || size != projectedViewport_ || projectedMesh_ != meshGeneration_) {
      const auto t0 = std::chrono::steady_clock::now();
      projectVertices(*mesh_, mvp, size, 0, screenVertices_);
      stats_.cpuShadingMs += msSince(t0);
      projectedViewProjection_ = mvp;
      projectedViewport_ = size;
      projectedMesh_ = meshGeneration_;
      boundsValid_ = false;
    }
    if (!boundsValid_) {
      const auto t0 = std::chrono::steady_clock::now();
      computeBucketBounds(screenVertices_, size, 0, shading_);
      stats_.cpuShadingMs += msSince(t0);
      boundsValid_ = true;
    }
  }
  stats_.nonEmptyBuckets = shading_.nonEmptyBuckets;
}

// ---------------------------------------------------------------------------------------
// [SECTION] Frame

void Renderer::setMeshUniforms(GLuint prog, const CameraMatrices& camera) {
  const glm::mat4 modelView = camera.view;  // the mesh is already centred and scaled
  gl::setUniform(prog, "uModelView", modelView);
  gl::setUniform(prog, "uProjection", camera.projection);
  gl::setUniform(prog, "uNormalMatrix", glm::transpose(glm::inverse(glm::mat3(modelView))));
}

void Renderer::drawBackground() {
  std::vector<std::string> d = {"QUAD_BACKGROUND"};
  if (palette_ && palette_->backgroundImage) d.push_back("BACKGROUND_IMAGE");
  Result<GLuint> prog = program("fullscreen.vert", "quad.frag", d);
  if (!prog) return;
  apply(kBackgroundPass);
  glUseProgram(*prog);
  if (palette_ && palette_->backgroundImage) {
    glActiveTexture(GL_TEXTURE0 + kUnitBackground);
    glBindTexture(GL_TEXTURE_2D, palette_->background.id());
    glActiveTexture(GL_TEXTURE0);
    gl::setUniform(*prog, "uBackground", int(kUnitBackground));
    gl::setUniform(*prog, "uBackgroundSize", palette_->backgroundSize);
  } else {
    gl::setUniform(*prog, "uBackgroundColour", palette_ ? palette_->backgroundColour : glm::vec3(1.0f));
  }
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats_.drawCalls;
}

void Renderer::drawBucket(int k) {
  // Bucket k's triangles from the bucketed index buffer, which the caller has bound.
  const std::uint32_t first = shading_.bucketStart[static_cast<size_t>(k)];
  const std::uint32_t count = shading_.bucketStart[static_cast<size_t>(k) + 1] - first;
  if (count == 0) return;
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count * 3), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 3 * sizeof(std::uint32_t)));
  ++stats_.drawCalls;
}

void Renderer::collectGpuTime() {
  // Queries finish in the order they were issued: read from the oldest pending one.
  for (int k = 0; k < kTimerSlots; ++k) {
    const int i = (timerIndex_ + k) % kTimerSlots;
    if (!timerPending_[i]) continue;
    GLint available = 0;
    glGetQueryObjectiv(timers_[i].id(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) continue;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(timers_[i].id(), GL_QUERY_RESULT, &ns);
    stats_.gpuMs = double(ns) * 1e-6;
    timerPending_[i] = false;
  }
}

Status Renderer::render(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  const auto frameStart = std::chrono::steady_clock::now();
  stats_.cpuShadingMs = 0.0;
  stats_.lightingRecomputes = stats_.bufferUploads = stats_.shaderBuilds = stats_.lutBuilds = stats_.drawCalls = 0;
  stats_.nonEmptyBuckets = 0;
  stats_.lines = 0;
  stats_.cpuLinesMs = 0.0;
  if (viewport.z < 1 || viewport.w < 1) return okStatus();  // minimised window: nothing to draw
  if (!palette_ && s.path != RenderPath::Reference) return Error{"no palette loaded"};
  if (palette_) if (Status st = ensureMatcher(s); !st) return st;

  collectGpuTime();
  const int timer = timerIndex_;
  const bool timing = !timerPending_[timer];
  if (timing) glBeginQuery(GL_TIME_ELAPSED, timers_[timer].id());

  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  apply(kMeshPass);
  glEnable(GL_SCISSOR_TEST);  // confines the clears to our viewport (split view)
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  if (s.drawBackground) drawBackground();

  Status result = okStatus();
  if (mesh_ && triangleCount_ > 0) {
    using Output = RenderSettings::Output;
    const bool geometry = s.output == Output::EyePosition || s.output == Output::EyeNormal;
    if (s.path == RenderPath::Stencil && s.output == Output::Image) {
      result = renderStencil(camera, s, viewport);
    } else if (geometry) {
      Result<GLuint> prog = program("mesh.vert", "mesh.frag", {s.output == Output::EyePosition ? "PATH_EYE_POSITION" : "PATH_EYE_NORMAL"});
      if (!prog) return Error{prog.error()};
      apply(kMeshPass);
      glUseProgram(*prog);
      setMeshUniforms(*prog, camera);
      glBindVertexArray(vao_.id());
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangleCount_ * 3), GL_UNSIGNED_INT, nullptr);
      ++stats_.drawCalls;
    } else {
      // The stencil path's entries are the triangle path's: show them the same way.
      RenderSettings eff = s;
      if (eff.path == RenderPath::Stencil) eff.path = RenderPath::Triangle;
      if (eff.path == RenderPath::Triangle) ensureTriangleShading(camera.view, camera, eff, viewport);
      // The triangle path's lighting happened on the CPU: its shader has no lighting at all.
      std::vector<std::string> d;
      if (eff.path != RenderPath::Triangle) d = lighting_.features().glslDefines();
      switch (eff.path) {
        case RenderPath::Triangle: d.push_back("PATH_TRIANGLE"); break;
        case RenderPath::Vertex: d.push_back("PATH_VERTEX"); d.push_back("PER_VERTEX_LIGHTING"); break;
        case RenderPath::Pixel: d.push_back("PATH_PIXEL"); break;
        case RenderPath::Smooth: d.push_back("PATH_SMOOTH"); break;
        case RenderPath::LitTextured: d.push_back("PATH_LIT_TEXTURED"); break;
        case RenderPath::Reference:
          if (eff.referenceGouraud) { d.push_back("PATH_GOURAUD"); d.push_back("PER_VERTEX_LIGHTING"); }
          else d.push_back("PATH_PHONG");
          break;
        case RenderPath::Stencil: break;
      }
      const bool usesPalette = eff.path != RenderPath::Reference;
      if (usesPalette) for (auto& x : paletteDefines(eff.match)) d.push_back(x);
      if (s.output == Output::PaletteEntry) d.push_back("OUTPUT_ENTRY");
      if (s.output == Output::PaletteBlend) d.push_back("OUTPUT_BLEND");
      Result<GLuint> prog = program("mesh.vert", "mesh.frag", d);
      if (!prog) {
        result = Error{prog.error()};
      } else {
        apply(kMeshPass);
        glUseProgram(*prog);
        setMeshUniforms(*prog, camera);
        if (eff.path != RenderPath::Triangle) uploadLightingUniforms(*prog, prepareLighting<float>(lighting_));
        if (usesPalette) bindPaletteTextures(*prog);
        glBindVertexArray(vao_.id());
        if (eff.path == RenderPath::Triangle) {
          glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bucketIndices_.id());
          for (int k = 0; k < paletteSize_; ++k) {
            if (shading_.bucketStart[static_cast<size_t>(k) + 1] == shading_.bucketStart[static_cast<size_t>(k)]) continue;
            gl::setUniform(*prog, "uEntry", k);
            drawBucket(k);
          }
        } else {
          glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
          glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangleCount_ * 3), GL_UNSIGNED_INT, nullptr);
          ++stats_.drawCalls;
        }
      }
    }
  }
  if (result && mesh_ && triangleCount_ > 0 && s.output == RenderSettings::Output::Image && s.lines.any()) {
    if (s.lines.imageSpace) result = drawImageSpaceEdges(camera, s.lines, viewport);
    if (result) result = drawLines(camera, s.lines, viewport);
  }
  if (timing) {
    glEndQuery(GL_TIME_ELAPSED);
    timerPending_[timer] = true;
    timerIndex_ = (timerIndex_ + 1) % kTimerSlots;
  }
  restoreDefaults();
  stats_.cpuFrameMs = msSince(frameStart);
  return result;
}

Status Renderer::renderStencil(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  ensureTriangleShading(camera.view, camera, s, viewport);
  Result<GLuint> mask = program("mesh.vert", "mesh.frag", {"PATH_MASK"});
  if (!mask) return Error{mask.error()};
  std::vector<std::string> bgDefines = {"QUAD_BACKGROUND"};
  if (palette_->backgroundImage) bgDefines.push_back("BACKGROUND_IMAGE");
  Result<GLuint> bgQuad = program("fullscreen.vert", "quad.frag", bgDefines);
  if (!bgQuad) return Error{bgQuad.error()};
  Result<GLuint> layerQuad = program("fullscreen.vert", "quad.frag", {"QUAD_LAYER"});
  if (!layerQuad) return Error{layerQuad.error()};

  glUseProgram(*mask);
  setMeshUniforms(*mask, camera);
  glUseProgram(*bgQuad);
  if (palette_->backgroundImage) {
    glActiveTexture(GL_TEXTURE0 + kUnitBackground);
    glBindTexture(GL_TEXTURE_2D, palette_->background.id());
    gl::setUniform(*bgQuad, "uBackground", int(kUnitBackground));
    gl::setUniform(*bgQuad, "uBackgroundSize", palette_->backgroundSize);
  } else {
    gl::setUniform(*bgQuad, "uBackgroundColour", palette_->backgroundColour);
  }
  glUseProgram(*layerQuad);
  glActiveTexture(GL_TEXTURE0 + kUnitPalette);
  glBindTexture(GL_TEXTURE_2D_ARRAY, palette_->layers.id());
  glActiveTexture(GL_TEXTURE0);
  gl::setUniform(*layerQuad, "uPalette", int(kUnitPalette));

  for (int k = 0; k < paletteSize_; ++k) {
    const std::uint32_t count = shading_.bucketStart[static_cast<size_t>(k) + 1] - shading_.bucketStart[static_cast<size_t>(k)];
    if (count == 0 && s.stencilSkipEmpty) continue;
    glm::ivec4 rect(viewport.x, viewport.y, viewport.z, viewport.w);
    if (s.stencilScissor) {
      const glm::ivec4& b = shading_.bucketBounds[static_cast<size_t>(k)];
      rect = glm::ivec4(viewport.x + b.x, viewport.y + b.y, b.z - b.x, b.w - b.y);
      if (count > 0 && (rect.z <= 0 || rect.w <= 0)) {
        // Entirely off screen: its triangles still write depth that later buckets test against.
        rect = glm::ivec4(viewport.x, viewport.y, 0, 0);
      }
    }
    // (1) mark the pixels where this bucket's triangles are visible so far
    apply(kStencilMask);
    glUseProgram(*mask);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bucketIndices_.id());
    drawBucket(k);
    if (rect.z <= 0 || rect.w <= 0) continue;
    glScissor(rect.x, rect.y, rect.z, rect.w);
    glBindVertexArray(emptyVao_.id());
    // (2) the background under the marked pixels
    apply(kStencilBackground);
    glUseProgram(*bgQuad);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // (3) the palette layer blended over it; the stencil mark is cleared as it is drawn
    apply(kStencilLayer);
    glUseProgram(*layerQuad);
    gl::setUniform(*layerQuad, "uLayer", k);
    gl::setUniform(*layerQuad, "uLayerSize", palette_->layerSizes[static_cast<size_t>(k)]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    stats_.drawCalls += 2;
  }
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  return okStatus();
}

Status Renderer::drawLines(const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport) {
  if (!ls.silhouettes && !ls.creases && !ls.boundaries) return okStatus();
  const auto t0 = std::chrono::steady_clock::now();
  if (!edges_) edges_ = std::make_unique<FeatureEdges>(*mesh_);
  if (!lineVao_) {
    lineVao_ = gl::createVertexArray();
    staticLineBuffer_ = gl::createBuffer();
    silhouetteBuffer_ = gl::createBuffer();
  }
  if ((ls.creases || ls.boundaries) && uploadedCreaseAngle_ != ls.creaseAngle) {
    const auto& lines = edges_->staticLines(ls.creaseAngle);
    glBindBuffer(GL_ARRAY_BUFFER, staticLineBuffer_.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(FeatureLine)), lines.data(), GL_STATIC_DRAW);
    staticLineCount_ = lines.size();
    uploadedCreaseAngle_ = ls.creaseAngle;
    ++stats_.bufferUploads;
  }
  const glm::vec3 eye = glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 0, 0, 1));
  if (ls.silhouettes && !(eye == silhouetteEye_)) {
    const auto& lines = edges_->silhouettes(eye);
    glBindBuffer(GL_ARRAY_BUFFER, silhouetteBuffer_.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(FeatureLine)), lines.data(), GL_STREAM_DRAW);
    silhouetteCount_ = lines.size();
    silhouetteEye_ = eye;
    ++stats_.bufferUploads;
  }
  stats_.cpuLinesMs += msSince(t0);
  std::vector<std::string> d;
  if (ls.sketchy) d.push_back("SKETCHY");
  if (ls.depthFalloff) d.push_back("DEPTH_FALLOFF");
  Result<GLuint> prog = program("lines.vert", "lines.frag", d);
  if (!prog) return Error{prog.error()};
  PassState state = kMeshPass;  // depth-tested against the model, but lines write no depth
  state.depthWrite = false;
  state.blend = true;
  apply(state);
  glDepthFunc(GL_LEQUAL);
  glUseProgram(*prog);
  gl::setUniform(*prog, "uModelViewProjection", camera.projection * camera.view);
  gl::setUniform(*prog, "uViewport", glm::vec2(viewport.z, viewport.w));
  gl::setUniform(*prog, "uWidth", std::max(ls.width, 0.5f));
  const glm::vec3 colours[3] = {ls.silhouetteColour, ls.creaseColour, ls.boundaryColour};
  gl::setUniformArray(*prog, "uColours", colours, 3);
  gl::setUniform(*prog, "uFalloffDepth", glm::length(eye));
  glBindVertexArray(lineVao_.id());
  const int repeat = ls.sketchy ? 3 : 1;
  auto drawBuffer = [&](const gl::Buffer& buffer, std::size_t first, std::size_t count) {
    if (count == 0) return;
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    const auto base = static_cast<std::uintptr_t>(first * sizeof(FeatureLine));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, a)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, b)));
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(FeatureLine), reinterpret_cast<void*>(base + offsetof(FeatureLine, kind)));
    for (GLuint a = 0; a < 3; ++a) glVertexAttribDivisor(a, GLuint(repeat));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count) * repeat);
    stats_.lines += static_cast<int>(count);
    ++stats_.drawCalls;
  };
  if (ls.silhouettes) drawBuffer(silhouetteBuffer_, 0, silhouetteCount_);
  if (ls.creases || ls.boundaries) {
    // Static lines are creases first, then boundaries: draw the parts asked for.
    const auto& lines = edges_->staticLines(ls.creaseAngle);
    const std::size_t creases = static_cast<std::size_t>(
        std::count_if(lines.begin(), lines.end(), [](const FeatureLine& l) { return l.kind == float(EdgeKind::Crease); }));
    if (ls.creases) drawBuffer(staticLineBuffer_, 0, creases);
    if (ls.boundaries) drawBuffer(staticLineBuffer_, creases, staticLineCount_ - creases);
  }
  glDepthFunc(GL_LESS);
  return okStatus();
}

Status Renderer::drawImageSpaceEdges(const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const glm::ivec2 size(viewport.z, viewport.w);
  if (size != edgeSize_) {
    edgeNormals_ = gl::createTexture();
    glBindTexture(GL_TEXTURE_2D, edgeNormals_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    edgeDepth_ = gl::createTexture();
    glBindTexture(GL_TEXTURE_2D, edgeDepth_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.x, size.y, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    edgeFbo_ = gl::createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, edgeFbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, edgeNormals_.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, edgeDepth_.id(), 0);
    edgeSize_ = size;
    ++stats_.bufferUploads;
  }
  // The geometry pass: normals and depth of what this frame shows.
  glBindFramebuffer(GL_FRAMEBUFFER, edgeFbo_.id());
  glViewport(0, 0, size.x, size.y);
  glClearColor(0, 0, 0, 0);
  apply(kMeshPass);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  Result<GLuint> geo = program("mesh.vert", "mesh.frag", {"PATH_EYE_NORMAL"});
  Result<GLuint> sobel = program("fullscreen.vert", "edges.frag", {});
  Status status = !geo ? Status(Error{geo.error()}) : !sobel ? Status(Error{sobel.error()}) : okStatus();
  if (status) {
    glUseProgram(*geo);
    setMeshUniforms(*geo, camera);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangleCount_ * 3), GL_UNSIGNED_INT, nullptr);
    // The full-screen pass over the frame.
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    PassState state = kBackgroundPass;
    state.blend = true;
    apply(state);
    glUseProgram(*sobel);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, edgeNormals_.id());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, edgeDepth_.id());
    glActiveTexture(GL_TEXTURE0);
    gl::setUniform(*sobel, "uNormals", 0);
    gl::setUniform(*sobel, "uDepth", 1);
    gl::setUniform(*sobel, "uOrigin", glm::ivec2(viewport.x, viewport.y));
    gl::setUniform(*sobel, "uProjection", glm::vec2(camera.projection[2][2], camera.projection[3][2]));
    gl::setUniform(*sobel, "uThreshold", std::max(ls.imageThreshold, 1e-3f));
    gl::setUniform(*sobel, "uInk", ls.silhouetteColour);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    stats_.drawCalls += 2;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  return status;
}

void Renderer::drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                          const glm::ivec4& viewport) {
  Result<GLuint> prog = program("marker.vert", "marker.frag", {});
  if (!prog) return;
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  apply(kBackgroundPass);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(*prog);
  gl::setUniform(*prog, "uViewProjection", camera.projection * camera.view);
  gl::setUniform(*prog, "uPosition", worldPosition);
  gl::setUniform(*prog, "uColour", colour);
  gl::setUniform(*prog, "uPointSize", pixels);
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_POINTS, 0, 1);
  glDisable(GL_PROGRAM_POINT_SIZE);
  restoreDefaults();
}

}  // namespace npr
