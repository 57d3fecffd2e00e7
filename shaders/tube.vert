#version 330 core
// Cylinder impostor: a quad spanning the bone, as wide as the cylinder, facing the eye.
layout(location = 0) in vec4 iA;       // end a (mm), radius (mm)
layout(location = 1) in vec4 iB;       // end b (mm), unused
layout(location = 2) in vec4 iColour;

uniform mat4 uView;
uniform mat4 uProj;
uniform int uOrtho;

out float vAcross;
out vec3 vSide;
out vec3 vFront;
out vec3 vAxisPoint;
out float vRadius;
out vec4 vColour;

void main() {
  vec3 a = (uView * vec4(iA.xyz, 1.0)).xyz;
  vec3 b = (uView * vec4(iB.xyz, 1.0)).xyz;
  float radius = iA.w;
  vec3 axis = b - a;
  float len = length(axis);
  axis = len > 1e-4 ? axis / len : vec3(0.0, 1.0, 0.0);
  vec3 mid = 0.5 * (a + b);
  vec3 toEye = uOrtho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-mid);
  vec3 side = cross(axis, toEye);
  float sideLen = length(side);
  side = sideLen > 1e-4 ? side / sideLen : vec3(1.0, 0.0, 0.0);
  vec3 front = normalize(cross(side, axis));
  if (dot(front, toEye) < 0.0) front = -front;

  float across = ((gl_VertexID & 1) == 0 ? -1.0 : 1.0) * 1.2;
  vec3 base = (gl_VertexID & 2) == 0 ? a : b;
  vAcross = across;
  vSide = side;
  vFront = front;
  vAxisPoint = base;
  vRadius = radius;
  vColour = iColour;
  gl_Position = uProj * vec4(base + side * across * radius, 1.0);
}
