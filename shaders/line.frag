#version 330 core
noperspective in float vAcross;
noperspective in float vAlong;
in float vHalfWidth;
in float vDash;
in vec4 vColour;

out vec4 fragColour;

void main() {
  float coverage = clamp(vHalfWidth + 0.5 - abs(vAcross), 0.0, 1.0);
  if (vDash > 0.0) {
    float m = mod(max(vAlong, 0.0), 2.0 * vDash);
    coverage *= clamp(vDash - m + 0.5, 0.0, 1.0) * clamp(m + 0.5, 0.0, 1.0);
  }
  if (coverage <= 0.0) discard;
  fragColour = vec4(vColour.rgb, vColour.a * coverage);
}
