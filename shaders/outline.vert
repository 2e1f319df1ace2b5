// Hardware outlines and the charcoal rim: the mesh's positions in eye space, for the geometry
// stage (outline.geom), which decides per triangle what, if anything, it becomes. The offset
// method has no geometry stage: its back faces come through the rasterizer's culling, pulled
// towards the eye by uOffset times their depth (the slides' k z; a constant polygon offset
// fails at depth). Scaling an eye-space point towards the eye keeps where it projects and
// changes only its depth.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelView;

#ifdef OUTLINE_OFFSET
uniform mat4 uProjection;
uniform float uOffset;
#else
out vec3 vEye;
#endif

void main() {
  vec3 eye = (uModelView * vec4(aPosition, 1.0)).xyz;
#ifdef OUTLINE_OFFSET
  gl_Position = uProjection * vec4(eye * (1.0 - uOffset), 1.0);
#else
  vEye = eye;
#endif
}
