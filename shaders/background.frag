#version 330 core
// Vertical gradient with a gentle vignette.
in vec2 vUv;

uniform vec4 uTop;
uniform vec4 uBottom;

out vec4 fragColour;

void main() {
  vec3 c = mix(uBottom.rgb, uTop.rgb, smoothstep(0.0, 1.0, vUv.y));
  float v = length(vUv - 0.5) * 1.25;
  c *= 1.0 - 0.25 * v * v;
  fragColour = vec4(c, 1.0);
}
