#include "ui/render/colour_vision.h"

#include <algorithm>
#include <cmath>

namespace ew::ui::colour {
namespace {

constexpr float kPi = 3.14159265358979f;

float decode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float encode(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 linear(const glm::vec3& srgb) { return {decode(srgb.r), decode(srgb.g), decode(srgb.b)}; }

// glm matrices are column-major: written here row by row, then transposed.
glm::mat3 rows(float a, float b, float c, float d, float e, float f, float g, float h, float i) {
  return glm::transpose(glm::mat3(a, b, c, d, e, f, g, h, i));
}

// Machado et al. (2009), severity 1.0 (their supplementary table), row by row.
glm::mat3 deficiencyMatrix(Vision v) {
  // clang-format off
  switch (v) {
    case Vision::Protanopia:
      return rows( 0.152286f,  1.052583f, -0.204868f,
                   0.114503f,  0.786281f,  0.099216f,
                  -0.003882f, -0.048116f,  1.051998f);
    case Vision::Deuteranopia:
      return rows( 0.367322f,  0.860646f, -0.227968f,
                   0.280085f,  0.672501f,  0.047413f,
                  -0.011820f,  0.042940f,  0.968881f);
    case Vision::Tritanopia:
      return rows( 1.255528f, -0.076749f, -0.178779f,
                  -0.078411f,  0.930809f,  0.147602f,
                   0.004733f,  0.691367f,  0.303900f);
    case Vision::Typical:
      break;
  }
  // clang-format on
  return glm::mat3(1.0f);
}

float labF(float t) {
  constexpr float d = 6.0f / 29.0f;
  return t > d * d * d ? std::cbrt(t) : t / (3.0f * d * d) + 4.0f / 29.0f;
}

float degrees(float rad) { return rad * 180.0f / kPi; }
float radians(float deg) { return deg * kPi / 180.0f; }

// Hue angle in degrees [0, 360), 0 for a neutral colour (Sharma et al.'s convention).
float hueDeg(float b, float a) {
  if (a == 0.0f && b == 0.0f) return 0.0f;
  const float h = degrees(std::atan2(b, a));
  return h < 0.0f ? h + 360.0f : h;
}

}  // namespace

const char* visionName(Vision v) {
  switch (v) {
    case Vision::Typical:
      return "typical";
    case Vision::Protanopia:
      return "protanopia";
    case Vision::Deuteranopia:
      return "deuteranopia";
    case Vision::Tritanopia:
      return "tritanopia";
  }
  return "?";
}

glm::vec3 seenAs(const glm::vec3& srgb, Vision v) {
  if (v == Vision::Typical) return srgb;
  const glm::vec3 seen = glm::clamp(deficiencyMatrix(v) * linear(srgb), 0.0f, 1.0f);
  return {encode(seen.r), encode(seen.g), encode(seen.b)};
}

glm::vec3 lab(const glm::vec3& srgb) {
  const glm::vec3 c = linear(srgb);
  // sRGB (D65) to XYZ, then relative to the D65 white.
  const float x = (0.4124564f * c.r + 0.3575761f * c.g + 0.1804375f * c.b) / 0.95047f;
  const float y = 0.2126729f * c.r + 0.7151522f * c.g + 0.0721750f * c.b;
  const float z = (0.0193339f * c.r + 0.1191920f * c.g + 0.9503041f * c.b) / 1.08883f;
  const float fx = labF(x), fy = labF(y), fz = labF(z);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

float deltaE2000(const glm::vec3& lab1, const glm::vec3& lab2) {
  const float c1 = std::hypot(lab1.y, lab1.z), c2 = std::hypot(lab2.y, lab2.z);
  const float cMean7 = std::pow(0.5f * (c1 + c2), 7.0f);
  const float g = 0.5f * (1.0f - std::sqrt(cMean7 / (cMean7 + std::pow(25.0f, 7.0f))));
  const float a1 = (1.0f + g) * lab1.y, a2 = (1.0f + g) * lab2.y;
  const float cp1 = std::hypot(a1, lab1.z), cp2 = std::hypot(a2, lab2.z);
  const float hp1 = hueDeg(lab1.z, a1), hp2 = hueDeg(lab2.z, a2);

  const float dL = lab2.x - lab1.x, dC = cp2 - cp1;
  float dh = 0.0f;
  if (cp1 * cp2 != 0.0f) {
    dh = hp2 - hp1;
    if (dh > 180.0f) dh -= 360.0f;
    if (dh < -180.0f) dh += 360.0f;
  }
  const float dH = 2.0f * std::sqrt(cp1 * cp2) * std::sin(radians(0.5f * dh));

  const float lMean = 0.5f * (lab1.x + lab2.x), cMean = 0.5f * (cp1 + cp2);
  float hMean = hp1 + hp2;
  if (cp1 * cp2 != 0.0f) {
    if (std::abs(hp1 - hp2) <= 180.0f)
      hMean *= 0.5f;
    else
      hMean = hMean < 360.0f ? 0.5f * (hMean + 360.0f) : 0.5f * (hMean - 360.0f);
  }
  const float t = 1.0f - 0.17f * std::cos(radians(hMean - 30.0f)) +
                  0.24f * std::cos(radians(2.0f * hMean)) +
                  0.32f * std::cos(radians(3.0f * hMean + 6.0f)) -
                  0.20f * std::cos(radians(4.0f * hMean - 63.0f));
  const float dTheta = 30.0f * std::exp(-std::pow((hMean - 275.0f) / 25.0f, 2.0f));
  const float cMeanP7 = std::pow(cMean, 7.0f);
  const float rc = 2.0f * std::sqrt(cMeanP7 / (cMeanP7 + std::pow(25.0f, 7.0f)));
  const float l50 = (lMean - 50.0f) * (lMean - 50.0f);
  const float sl = 1.0f + 0.015f * l50 / std::sqrt(20.0f + l50);
  const float sc = 1.0f + 0.045f * cMean, sh = 1.0f + 0.015f * cMean * t;
  const float rt = -std::sin(radians(2.0f * dTheta)) * rc;
  const float l = dL / sl, c = dC / sc, h = dH / sh;
  return std::sqrt(l * l + c * c + h * h + rt * c * h);
}

float difference(const glm::vec3& a, const glm::vec3& b, Vision v) {
  return deltaE2000(lab(seenAs(a, v)), lab(seenAs(b, v)));
}

glm::vec3 over(const glm::vec4& colour, const glm::vec3& background) {
  return glm::mix(background, glm::vec3(colour), colour.a);
}

}  // namespace ew::ui::colour
