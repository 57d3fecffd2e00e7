#version 330 core
// Shades the impostor quad as a sphere (uMode 0) or as a flat glowing point-light
// (uMode 1, the 2D view's dots). Edges are anti-aliased through alpha (alpha-to-coverage
// on the multisampled target, or blending).
in vec2 vCorner;
in vec3 vCentreView;
in float vRadius;
in vec4 vColour;

uniform mat4 uProj;
uniform int uMode;

out vec4 fragColour;

vec3 shade(vec3 base, vec3 n) {
  vec3 key = normalize(vec3(-0.45, 0.65, 0.62));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.75));
  float diffuse = max(dot(n, key), 0.0) * 0.72 + max(dot(n, fill), 0.0) * 0.22;
  vec3 h = normalize(key + vec3(0.0, 0.0, 1.0));
  float spec = pow(max(dot(n, h), 0.0), 40.0) * 0.32;
  float rim = pow(1.0 - max(n.z, 0.0), 3.0) * 0.18;
  return base * (0.30 + diffuse) + vec3(spec + rim);
}

void main() {
  float d = length(vCorner);
  float aa = max(fwidth(d), 1e-4);
  if (uMode == 1) {
    float core = 1.0 - smoothstep(0.55 - aa, 0.55 + aa, d);
    float halo = exp(-5.0 * d * d) * 0.55;
    float a = max(core, halo) * vColour.a;
    if (a < 0.003) discard;
    fragColour = vec4(vColour.rgb * (0.6 + 0.4 * core) + vec3(0.35 * core), a);
    gl_FragDepth = gl_FragCoord.z;
    return;
  }
  float coverage = 1.0 - smoothstep(1.0 - aa, 1.0 + aa, d);
  if (coverage <= 0.0) discard;
  vec2 xy = d > 1.0 ? vCorner / d : vCorner;
  vec3 n = vec3(xy, sqrt(max(0.0, 1.0 - dot(xy, xy))));
  vec3 p = vCentreView + n * vRadius;
  vec4 clip = uProj * vec4(p, 1.0);
  gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
  fragColour = vec4(shade(vColour.rgb, n), vColour.a * coverage);
}
