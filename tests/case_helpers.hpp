#pragma once
// Helpers for app-level tests: run example cases in-process and compare probes with exact
// fields.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/probes2d.hpp"
#include "tests/test_paths.hpp"

namespace magfem::test {

inline std::string example(const std::string& relative) {
  return std::string(magfem::test::source_dir()) + "/examples/" + relative;
}

// A small actuator the suite can solve by FE in seconds: a 2 x 4 segment array (7..10 mm) on
// the rotor inside six ring coils on the sphere (11..14 mm), three above and three below the
// equator, no iron; the refined air over the coils starts at mid-gap, apart from the turning
// rotor. Coarse on purpose (68k tetrahedra at order 2, a few seconds).
inline const char* small_actuator_case = R"(title: small spherical actuator (test)
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: m, shape: segment_array, r_inner: 7, r_outer: 10, theta: [0, 180], phi: [0, 360],
     p_theta: 2, p_phi: 4, material: pm, pattern: {type: parallel_alternating, convention: centre},
     group: rotor, mesh_size: 3}
  - {name: coil_space, shape: spherical_segment, r_inner: 10.5, r_outer: 15, mesh_size: 2.5}
coils:
  - {name: a1, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [60, 0], turns: 100, current: 0, fill_factor: 0.7, group: stator}
  - {name: a2, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [60, 120], turns: 100, current: 0, fill_factor: 0.7, group: stator}
  - {name: a3, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [60, 240], turns: 100, current: 0, fill_factor: 0.7, group: stator}
  - {name: b1, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [120, 60], turns: 100, current: 0, fill_factor: 0.7, group: stator}
  - {name: b2, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [120, 180], turns: 100, current: 0, fill_factor: 0.7, group: stator}
  - {name: b3, shape: circular_coil_on_sphere, r_inner: 11, r_outer: 14, gap_angle: 4, bundle_width: 16, axis_angles: [120, 300], turns: 100, current: 0, fill_factor: 0.7, group: stator}
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 6, chord_tolerance: 0.3}
solver: {order: 2}
)";

// Writes `text` to a fresh temporary case file and returns its path.
// Thick solenoid in air (examples/axi/solenoid.yaml's winding: r 10..15 mm, z -15..15 mm, 500
// turns at 2 A), meshed coarsely so that an adaptive loop has to find where the sizes matter.
// Exact energy L I^2 / 2 with Maxwell's self-inductance (analytic/coil_closed_forms.hpp).
inline const char* coarse_solenoid_case = R"(
dimension: axi
unit: mm
regions:
  - {name: winding, shape: rectangle, center: [12.5, 0], width: 5, height: 30, turns: 500,
     current: 2.0, mesh_size: 4.0}
boundary: {type: open, radius: 40, shell_ratio: 1.5}
mesh: {size: 8.0, chord_tolerance: 0.002}
solver: {order: 2}
)";

// A planar magnet disk (B_r 1.2 T, at x = -6 mm) beside an iron disk of `iron` (at x = 6 mm) in
// an open boundary, meshed coarsely (seconds): the case up to its mesh, to which a test
// appends solver, probes or forces.
inline std::string magnet_and_iron_disks_case2d(const std::string& iron) {
  return R"(unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.05}
regions:
  - {name: magnet, shape: disk, center: [-6, 0], radius: 4, material: pm,
     magnetization: {type: parallel, angle: 0}}
  - {name: iron, shape: disk, center: [6, 0], radius: 5, material: )" +
         iron + R"(}
boundary: {type: open, radius: 30}
mesh: {size: 3}
)";
}

// The uniformly magnetized sphere of examples/3d/magnetized_sphere.yaml (radius 10 mm, B_r
// 1 T, mu_r 1, magnetized along +z) with its own mesh size (mm): the case up to its
// boundary, to which a test appends boundary, mesh, solver and what it checks. Exact: B
// inside (2/3) B_r, outside a dipole, energy mu0 M^2 V / 6.
inline std::string magnetized_sphere_case3d(const std::string& mesh_size) {
  return R"(
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: sphere, shape: spherical_segment, r_inner: 0, r_outer: 10, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: )" +
         mesh_size + "}\n";
}

// A steel_1010 rod (r 0..4 mm, z -8..8 mm, mesh size 3) inside a solenoid (r 5..8 mm, z -6..6
// mm, 1000 turns at `current` A) in an open boundary at 20 mm, coarse (seconds at order 1):
// at 3 A the rod's middle reaches ~1.7 T, the knee and beyond. The rod does not encircle the
// coil's current: a total-potential region, whose H is -grad(u + Phi_s). `solver`: the
// solver block's YAML flow map, e.g. "{order: 1}"; a test may append probes.
inline std::string rod_in_solenoid_case3d(double current, const std::string& solver) {
  char amperes[32];
  std::snprintf(amperes, sizeof amperes, "%.17g", current);
  return std::string(R"(unit: mm
dimension: 3
regions:
  - {name: rod, shape: cylinder, r_outer: 4, height: 16, material: steel_1010,
     placement: {translate: [0, 0, -8]}, mesh_size: 3}
coils:
  - {name: coil, shape: solenoid, r_inner: 5, r_outer: 8, length: 12, center: [0, 0, 0],
     axis: [0, 0, 1], turns: 1000, current: )") +
         amperes + R"(}
boundary: {type: open, radius: 20}
mesh: {size: 12, chord_tolerance: 0.3}
solver: )" +
         solver + R"(
output: {vtu: false}
)";
}

inline std::string write_temp_case(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// The example's text (path relative to examples/) with its `boundary.symmetry` key (an inline
// list, or a block list below it) removed: the same device as a full model. Empty if the
// example has no such key.
inline std::string example_without_symmetry(const std::string& relative) {
  std::ifstream in(example(relative));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string out =
      std::regex_replace(text, std::regex("\n *symmetry:[^\n]*(\n +- [^\n]*)*"), "");
  return out == text ? std::string() : out;
}

// The entry called `name` of a run's forces (or anything with a `name`); throws if none.
template <class Named>
const Named& named(const std::vector<Named>& entries, const std::string& name) {
  for (const auto& e : entries)
    if (e.name == name)
      return e;
  throw std::runtime_error("no entry named " + name);
}

inline const ProbeTable& probe(const Run2D& run, const std::string& name) {
  for (const auto& p : run.probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe " + name);
}

// The probe `name` of a 2D run read from the element field itself instead of the patch
// recovery the pipeline writes (to compare the two).
inline ProbeTable element_probe(const Run2D& run, const std::string& name) {
  for (const auto& p : run.spec.probes)
    if (p.name == name)
      return sample_probe_2d(*run.field, PointLocator2D(run.mesh), p, run.spec.length_unit);
  throw std::runtime_error("no probe " + name);
}

// One solve of a 3D case without its adapt: block, on its own mesh (sizes empty) or with the
// size sources of an adaptive pass added to its sizes.
inline std::unique_ptr<Run3D> solve_with_sizes_3d(const CaseSpec& spec,
                                                  std::vector<SizeSample3D> sizes,
                                                  const RunOverrides& overrides = {}) {
  CaseSpec s = spec;
  s.adapt = {};
  if (!sizes.empty())
    s.geometry3d.options.refine_sizes =
        std::make_shared<const std::vector<SizeSample3D>>(std::move(sizes));
  return run_case_3d(s, overrides);
}

} // namespace magfem::test
