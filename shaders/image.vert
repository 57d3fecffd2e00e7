#version 330 core
// A picture on the rectangle [uLow, uHigh] of the plane z = 0 (a video frame in the 2D view).
uniform mat4 uViewProj;
uniform vec2 uLow;
uniform vec2 uHigh;

out vec2 vUv;

void main() {
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? 0.0 : 1.0, (gl_VertexID & 2) == 0 ? 0.0 : 1.0);
  // The picture's rows run top to bottom: its top row at uHigh.y.
  vUv = vec2(corner.x, 1.0 - corner.y);
  gl_Position = uViewProj * vec4(mix(uLow, uHigh, corner), 0.0, 1.0);
}
