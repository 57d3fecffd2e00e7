#include "ui/app/tour.h"

#include <array>

namespace ew::ui {

namespace {

constexpr std::array<TourStep, 6> kSteps{{
    {TourAnchor::BottomCentre, "What an eigenwalker is",
     "A walker is one gait cycle of 15 joints, summarised by a Fourier series with two "
     "harmonics: 225 numbers per person. Principal components over many walkers give the "
     "eigenwalkers, the directions in which human gaits differ most. Here the first "
     "eigenwalker is set to +2.5 standard deviations; drag the Coefficients panel's sliders to "
     "see what the others change.",
     R"([{"drawer_tab": "coefficients"}, {"set_mode": "explore"}, {"overlay": ["point_lights", false]}, {"show_panel": ["analysis", false]},
         {"reset_coefficients": null}, {"set_coefficient": [1, 2.5]}, {"set_camera": "three_quarter"},
         {"play": true}])"},
    {TourAnchor::BottomCentre, "Directions that mean something",
     "Eigenwalkers are the directions in which gaits differ most, not directions with names. "
     "Regressing the walkers on what is known or measured about them (speed, height, leg "
     "length, arm swing; in the default population also sex) gives an axis for each "
     "(Troje, 2002). Here the mean walker has been moved along the speed axis to 1.6 m/s: "
     "longer strides, quicker steps, more arm swing. Drag the semantic sliders at the top of the "
     "Coefficients panel; hover one to see how well the walkers predict it.",
     R"([{"drawer_tab": "coefficients"}, {"set_mode": "explore"}, {"reset_coefficients": null},
         {"set_semantic": {"attribute": "measured_speed_mps", "value": 1.6}}, {"set_camera": "side"},
         {"play": true}])"},
    {TourAnchor::BottomCentre, "The 2D to 3D ambiguity",
     "Left: all the reconstruction sees, the walker's joints projected orthographically at "
     "the view angle α, here 0°, straight from the front, where depth is lost completely. "
     "Shown as point-lights (Johansson, 1973), the dots are still clearly a person walking. "
     "Right: the 3D walker recovered from these dots with a model that never saw this "
     "subject.",
     R"([{"drawer_tab": "controls"}, {"set_mode": "reconstruct"}, {"unknown_angle": false}, {"set_method": "map"}, {"set_angle": 0},
         {"overlay": ["point_lights", true]}, {"set_camera": "side"}, {"play": true}])"},
    {TourAnchor::BottomCentre, "LSQ versus MAP",
     "LSQ picks the eigenwalker coefficients that reproduce the 2D dots best. Near frontal "
     "views many 3D walkers fit equally well, and LSQ over-fits. MAP adds the prior that a "
     "walker is typical (Gaussian in eigenwalker space, with image noise σ²). The analysis "
     "window plots the error against the view angle: MAP (amber) stays below LSQ (blue) "
     "where the view is ambiguous.",
     R"([{"overlay": ["point_lights", false]}, {"set_method": "lsq"}, {"set_angle": 0},
         {"set_analysis_metric": "E_a"}, {"show_panel": ["analysis", true]}])"},
    {TourAnchor::BottomLeft, "Unknown view angle, mirror ambiguity",
     "Usually α is unknown. The viewer searches the angle whose reconstruction explains the "
     "input best: the profile J(α) (the View panel). The dots alone cannot tell α from −α: a walker "
     "seen from there with its depth reversed casts the same image. J(α) has a second dip "
     "near −α, but on its logarithmic scale it lies far above the best fit: a depth-reversed "
     "walker is a mirror image, and the model knows people do not walk like that. In 3D the "
     "red camera is the estimate, the teal one the truth.",
     R"([{"drawer_tab": "view"}, {"show_panel": ["analysis", false]}, {"set_method": "map"}, {"set_angle": 45}, {"unknown_angle": true},
         {"set_camera": "top"}])"},
    {TourAnchor::BottomRight, "What the errors mean",
     "The blue ghost is the truth; magenta lines join each true joint to its reconstruction. "
     "E_a is the mean squared depth error over the cycle (mm²). E_r divides it by the depth "
     "variance the view hides, so E_r = 1 is no better than guessing the average walker. "
     "MPJPE is the mean 3D distance per joint (mm). The Errors panel's bars give each joint's "
     "depth error.",
     R"([{"drawer_tab": "errors"}, {"unknown_angle": false}, {"set_angle": 45}, {"set_camera": "three_quarter"},
         {"overlay": ["ghost", true]}, {"overlay": ["error_lines", true]}, {"overlay": ["depth_error", true]},
         {"overlay": ["error_bars", true]}, {"overlay": ["metrics", true]}])"},
}};

}  // namespace

std::span<const TourStep> tourSteps() { return kSteps; }

}  // namespace ew::ui
