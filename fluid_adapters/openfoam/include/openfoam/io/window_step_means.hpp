#pragma once

#include <span>
#include <string>

#include "openfoam/io/case_layout.hpp"
#include "openfoam/io/foam_fields.hpp"

namespace openfoam {

// What the soil receives for a window is what the water gave it over the
// window's steps: the mean of the steps' pressures,
//   p_bar = (1 / N) sum_k p_k          (fixed steps),
// whose gradient times the window is the impulse of -phi_s grad p (Tran et
// al., MPMICE, eq. 7), and the mean of the cloud's momentum source, so that
// UTrans_bar x N is the drag's momentum over the window. The last step alone
// is neither: restarted every window, MPPICInterFoam's pressure and drag
// alternate from step to step near the soil (on the subaerial slide, 205 /
// 1480 Pa at the first / second step of a window ahead of the grains' front,
// a continuous run relaxing to about 940 Pa), and with an even number of
// steps per window its end always falls on the same side: the water barely
// moved while the last step's gradient, sent to the soil, pushed the grains
// up the plane at several times g.
//
// `step_times` are the time directories holding p and kinematicCloud:UTrans
// of the window's steps before its end (control_dict's write_steps_between);
// `end` holds the last step's fields and gets the means (its cloud momentum
// only when it has one).
void average_over_window_steps(const CaseLayout& layout, std::span<const std::string> step_times,
                               FoamFields& end, int dim);

}  // namespace openfoam
