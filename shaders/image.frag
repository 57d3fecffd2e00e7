#version 330 core
in vec2 vUv;

uniform sampler2D uImage;
uniform float uBrightness;

out vec4 fragColour;

void main() { fragColour = vec4(texture(uImage, vUv).rgb * uBrightness, 1.0); }
