// Headless sessions (see headless_session.h).
#include "app/headless/headless_session.h"

namespace npr {

Result<HeadlessSession> openHeadlessSession(bool debug) {
  auto ctx = HeadlessContext::create(debug);
  if (!ctx) return Error{ctx.error()};
  auto renderer = Renderer::create();
  if (!renderer) return Error{renderer.error()};
  return HeadlessSession{std::move(*ctx), std::move(*renderer)};
}

}  // namespace npr
