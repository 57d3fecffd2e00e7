#version 330 core
// Procedural floor grid (10 cm minor, 50 cm major lines, anti-aliased with fwidth),
// fading towards the edge, with a soft contact shadow under the walker.
in vec2 vWorld;

uniform float uExtent;
uniform float uScroll;       // mm along y (treadmill)
uniform vec2 uShadowCentre;
uniform float uShadowRadius;

out vec4 fragColour;

float gridLine(vec2 p, float spacing, float widthPx) {
  vec2 cell = abs(fract(p / spacing - 0.5) - 0.5) * spacing;
  vec2 px = cell / max(fwidth(p), vec2(1e-4));
  float d = min(px.x, px.y);
  return 1.0 - clamp(d - 0.5 * widthPx + 0.5, 0.0, 1.0);
}

void main() {
  vec2 p = vWorld + vec2(0.0, uScroll);
  float r = length(vWorld) / uExtent;
  float fade = 1.0 - smoothstep(0.45, 1.0, r);
  vec3 floorColour = vec3(0.11, 0.12, 0.14);
  vec3 colour = floorColour;
  colour = mix(colour, vec3(0.24, 0.26, 0.30), gridLine(p, 100.0, 1.0) * 0.6);
  colour = mix(colour, vec3(0.38, 0.42, 0.47), gridLine(p, 500.0, 1.6) * 0.85);
  float shadow = exp(-pow(length(vWorld - uShadowCentre) / uShadowRadius, 2.0)) * 0.55;
  colour *= 1.0 - shadow;
  fragColour = vec4(colour, 0.92 * fade);
}
