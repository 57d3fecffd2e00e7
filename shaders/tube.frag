#version 330 core
in float vAcross;
in vec3 vSide;
in vec3 vFront;
in vec3 vAxisPoint;
in float vRadius;
in vec4 vColour;

uniform mat4 uProj;

out vec4 fragColour;

vec3 shade(vec3 base, vec3 n) {
  vec3 key = normalize(vec3(-0.45, 0.65, 0.62));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.75));
  float diffuse = max(dot(n, key), 0.0) * 0.72 + max(dot(n, fill), 0.0) * 0.22;
  vec3 h = normalize(key + vec3(0.0, 0.0, 1.0));
  float spec = pow(max(dot(n, h), 0.0), 40.0) * 0.25;
  float rim = pow(1.0 - max(n.z, 0.0), 3.0) * 0.15;
  return base * (0.30 + diffuse) + vec3(spec + rim);
}

void main() {
  float t = abs(vAcross);
  float aa = max(fwidth(vAcross), 1e-4);
  float coverage = 1.0 - smoothstep(1.0 - aa, 1.0 + aa, t);
  if (coverage <= 0.0) discard;
  float s = clamp(vAcross, -1.0, 1.0);
  float h = sqrt(max(0.0, 1.0 - s * s));
  vec3 n = normalize(vSide * s + vFront * h);
  vec3 p = vAxisPoint + vSide * s * vRadius + vFront * h * vRadius;
  vec4 clip = uProj * vec4(p, 1.0);
  gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
  fragColour = vec4(shade(vColour.rgb, n), vColour.a * coverage);
}
