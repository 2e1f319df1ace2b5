// The depth cue (renderer/features/depth_cue/): each model's surface again, at exactly the depth
// its path left (gl_Position as mesh.vert computes it, invariant), with its eye distance.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModelView;
uniform mat4 uProjection;
invariant gl_Position;
out float vDistance;
void main() {
  vec4 eye = uModelView * vec4(aPosition, 1.0);
  gl_Position = uProjection * eye;
  vDistance = length(eye.xyz);
}
