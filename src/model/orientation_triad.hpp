// The local triad of a rectangular *ORIENTATION (keywords.md §6, connection-types.md §1.3):
// e1 along a − c, e3 normal to the plane of a, b, c, e2 = e3 × e1, then the optional extra
// rotation about one local axis. Pure math shared by the reader, the validator and kinematics.
#pragma once

#include <cstdint>

#include "src/model/section_model.hpp"

namespace clinch {

struct Model;

enum class TriadStatus : std::uint8_t { Ok, PointAAtOrigin, PointBOnAxis };

// Computes the triad from points a, b, c (global or part coordinates), then rotates it by
// `angle_degrees` about local axis `axis` (1, 2 or 3; right-hand rule). On a degenerate input
// `out` is left unchanged and the status names the fault (keywords.md §6 steps 1–2).
TriadStatus orientation_triad(const Vec3& a, const Vec3& b, const Vec3& c, int axis,
                              double angle_degrees, Triad& out);

// Rotates a triad by `angle_degrees` about its own axis k (§6 step 4): for k = 1
// e2' = cos θ e2 + sin θ e3, e3' = −sin θ e2 + cos θ e3; k = 2, 3 by cyclic permutation.
Triad rotate_about_local_axis(const Triad& triad, int axis, double angle_degrees);

// The triad of `orientation` as placed by `instance` (global directions): orientations written
// in a part turn with each instance's rotation (keywords.md §6 step 5); others are returned as is.
Triad placed_triad(const Model& model, const Orientation& orientation, std::int32_t instance);

}  // namespace clinch
