#version 330 core
// The floor square (z = 0), corners from gl_VertexID.
uniform mat4 uView;
uniform mat4 uProj;
uniform float uExtent;

out vec2 vWorld;

void main() {
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, (gl_VertexID & 2) == 0 ? -1.0 : 1.0);
  vWorld = corner * uExtent;
  gl_Position = uProj * uView * vec4(vWorld, 0.0, 1.0);
}
