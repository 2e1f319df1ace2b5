// Ambient occlusion bake: the vertex's sample, added to its texel by the blender.
in vec2 vSample;
out vec4 fragColor;
void main() { fragColor = vec4(vSample, 0.0, 0.0); }
