// The light marker: one point sprite at a world position, drawn over the scene.
uniform mat4 uViewProjection;
uniform vec3 uPosition;
uniform float uPointSize;
void main() {
  gl_Position = uViewProjection * vec4(uPosition, 1.0);
  gl_PointSize = uPointSize;
}
