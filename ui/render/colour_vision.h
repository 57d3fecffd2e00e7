#pragma once
// How far apart two of the viewer's colours look, to a typical eye and to the common colour
// vision deficiencies, so that the palette can be checked rather than trusted.
//
// - Deficiencies: Machado, Oliveira & Fernandes (2009), "A physiologically-based model for
//   simulation of color vision deficiency", IEEE TVCG 15(6):1291-1298, their matrices at
//   severity 1.0 (protanopia, deuteranopia, tritanopia) applied to linear sRGB.
// - Difference: CIEDE2000 (Sharma, Wu & Dalal 2005, "The CIEDE2000 color-difference
//   formula: implementation notes, supplementary test data, and mathematical observations",
//   Color Research & Application 30(1):21-30) in CIELAB under D65.
// Colours are sRGB-encoded, components in [0, 1], as the palette writes them.

#include <glm/glm.hpp>

namespace ew::ui::colour {

enum class Vision { Typical, Protanopia, Deuteranopia, Tritanopia };
inline constexpr Vision kVisions[] = {Vision::Typical, Vision::Protanopia, Vision::Deuteranopia,
                                      Vision::Tritanopia};
const char* visionName(Vision v);

// The colour as the given vision sees it (sRGB in, sRGB out, clamped to the gamut).
glm::vec3 seenAs(const glm::vec3& srgb, Vision v);

// CIELAB (L* in [0, 100]) of an sRGB colour, D65 white.
glm::vec3 lab(const glm::vec3& srgb);

// CIEDE2000 between two CIELAB colours (kL = kC = kH = 1).
float deltaE2000(const glm::vec3& lab1, const glm::vec3& lab2);

// CIEDE2000 between two sRGB colours as the given vision sees them.
float difference(const glm::vec3& a, const glm::vec3& b, Vision v);

// A translucent colour over an opaque background, blended as GL blends it (in the encoded
// values: the viewer draws into a plain, not an sRGB, framebuffer).
glm::vec3 over(const glm::vec4& colour, const glm::vec3& background);

}  // namespace ew::ui::colour
