// GPU lighting probe (see lighting_probe.h).
#include "support/lighting_probe.h"

#include <cstddef>

#include "renderer/gl/offscreen_target.h"
#include "renderer/gl/pass_state.h"
#include "renderer/gl/shader_program.h"
#include "renderer/lighting/lighting_uniforms.h"

namespace npr {

Result<std::vector<glm::vec3>> evaluateLightingOnGpu(const LightingState& state, const std::vector<LightingSample>& samples) {
  if (samples.empty()) return std::vector<glm::vec3>{};
  const int width = 256;
  const int height = static_cast<int>((samples.size() + width - 1) / width);
  Result<gl::ShaderProgram> prog = gl::ShaderProgram::build("lighting_probe.vert", "lighting_probe.frag", state.features().glslDefines());
  if (!prog) return Error{prog.error()};
  Result<OffscreenTarget> target = OffscreenTarget::create(width, height, OffscreenTarget::Format::RGBA32F);
  if (!target) return Error{target.error()};
  struct Vertex { glm::vec3 p, n; float back; };
  std::vector<Vertex> verts;
  verts.reserve(samples.size());
  for (const auto& s : samples) verts.push_back({s.position, s.normal, s.back ? 1.0f : 0.0f});
  gl::VertexArray vao = gl::createVertexArray();
  gl::Buffer vbo = gl::createBuffer();
  glBindVertexArray(vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, vbo.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts.size() * sizeof(Vertex)), verts.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, p)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, n)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, back)));
  target->bind();
  gl::apply(gl::pass::kBackground);  // no depth, no blending
  prog->use();
  prog->set("uSize", glm::ivec2(width, height));
  uploadLightingUniforms(*prog, prepareLighting<float>(state));
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(verts.size()));
  const ImageRGBA32F img = target->readRGBA32F();
  glBindVertexArray(0);
  glUseProgram(0);
  std::vector<glm::vec3> out(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    // Read-back is top row first; point i sits at GL row i / width, counted from the bottom.
    const size_t x = i % width, y = static_cast<size_t>(height - 1) - i / width;
    const float* p = &img.pixels[(y * width + x) * 4];
    out[i] = {p[0], p[1], p[2]};
  }
  return out;
}

}  // namespace npr
