#version 330 core
// Sphere impostor: a camera-facing quad around each joint; the fragment shader shades it
// as a sphere and writes the sphere's depth.
layout(location = 0) in vec4 iCentreRadius;  // centre (mm), radius (mm)
layout(location = 1) in vec4 iColour;

uniform mat4 uView;
uniform mat4 uProj;
uniform float uMargin;  // quad half-size in radii (> 1 leaves room for the soft rim)

out vec2 vCorner;
out vec3 vCentreView;
out float vRadius;
out vec4 vColour;

void main() {
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, (gl_VertexID & 2) == 0 ? -1.0 : 1.0);
  vec3 centre = (uView * vec4(iCentreRadius.xyz, 1.0)).xyz;
  float radius = iCentreRadius.w;
  vCorner = corner * uMargin;
  vCentreView = centre;
  vRadius = radius;
  vColour = iColour;
  gl_Position = uProj * vec4(centre + vec3(vCorner * radius, 0.0), 1.0);
}
