#pragma once
// `magfem sweep CASE --rotate GROUP --axis z --angles ...` for planar 2D cases: a motor's
// rotor turned step by step (cogging torque, torque against rotor angle), a magnet turned
// between poles. Every region of the group turns about the point (--point, default the
// origin), magnetizations with it; each position is a new mesh and solve, and the row holds
// the torque about the point and the force on the group (per metre, or per stack with
// `stack_length`), in the 3D sweep's columns (Tz, Fx, Fy; the others zero).
//
// `magfem sweep CASE --move GROUP --axis x|y|dx,dy --positions ...` (mm) translates the group
// in the plane instead (force against gap): the rows are the 3D translate sweep's
// (position_mm, Tx..Fz), the torque about the point carried with the group.
//
// The force on the group, in this order: the Lorentz force on its current regions; else the
// case's one `band` force (Arkkio's band, the most accurate for torque), else its one
// `circle` force: the stress tensor on what they enclose, which must be the group (their
// centre turns or moves with it). Otherwise bad input that says which entry to add.
#include <functional>

#include "casefile/case_spec.hpp"
#include "studies/sweep.hpp"

namespace magfem {

// The case with every region of `group` turned by angle_rad (counter-clockwise) about
// `point` (metres; z ignored). Throws InputError (naming --rotate) if the case is not planar
// 2D or no region is in the group.
CaseSpec rotate_group_planar(const CaseSpec& spec, const std::string& group, double angle_rad,
                             const Eigen::Vector3d& point);

// The case with every region of `group` moved by `displacement` (metres; z ignored),
// magnetizations and the stress circles and bands with it. Throws InputError (naming --move)
// if the case is not planar 2D or no region is in the group.
CaseSpec translate_group_planar(const CaseSpec& spec, const std::string& group,
                                const Eigen::Vector3d& displacement);

// options.motion: rotate (options.axis must be z) or translate (options.axis in the plane,
// offsets_m); surface_radius and analytic are not for planar cases (InputError).
std::vector<SweepRow> run_sweep_planar(const CaseSpec& spec, const SweepOptions& options,
                                       const SweepProgress& progress = {},
                                       SweepJobs* jobs = nullptr);

} // namespace magfem
