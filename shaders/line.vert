#version 330 core
// Anti-aliased line of constant pixel width: each instance is a quad expanded in screen
// space around the projected segment.
layout(location = 0) in vec4 iA;       // end a (mm), width (px)
layout(location = 1) in vec4 iB;       // end b (mm), dash length (px, 0 = solid)
layout(location = 2) in vec4 iColour;

uniform mat4 uView;
uniform mat4 uProj;
uniform vec2 uViewport;  // px

noperspective out float vAcross;  // px from the centre line
noperspective out float vAlong;   // px from end a
out float vHalfWidth;
out float vDash;
out vec4 vColour;

void main() {
  vec4 ca = uProj * uView * vec4(iA.xyz, 1.0);
  vec4 cb = uProj * uView * vec4(iB.xyz, 1.0);
  vec2 sa = ca.xy / ca.w * 0.5 * uViewport;
  vec2 sb = cb.xy / cb.w * 0.5 * uViewport;
  vec2 dir = sb - sa;
  float len = length(dir);
  dir = len > 1e-4 ? dir / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float halfWidth = 0.5 * iA.w;
  float extent = halfWidth + 1.0;  // one pixel of room for the anti-aliased edge

  bool atB = (gl_VertexID & 2) != 0;
  float side = (gl_VertexID & 1) == 0 ? -1.0 : 1.0;
  vec4 c = atB ? cb : ca;
  vec2 s = (atB ? sb : sa) + normal * side * extent + dir * (atB ? extent : -extent);
  gl_Position = vec4(s / (0.5 * uViewport) * c.w, c.z, c.w);
  vAcross = side * extent;
  vAlong = atB ? len + extent : -extent;
  vHalfWidth = halfWidth;
  vDash = iB.w;
  vColour = iColour;
}
