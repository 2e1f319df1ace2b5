// Hardware outlines and the charcoal rim (outline.geom): the mesh's positions in eye space.
// The geometry stage decides per triangle what, if anything, it becomes.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelView;

out vec3 vEye;

void main() { vEye = (uModelView * vec4(aPosition, 1.0)).xyz; }
