#pragma once
// Everything a case file says, validated and converted to SI units (metres, radians, tesla,
// A/m^2). Built by read_case(); consumed by the mesh, solver and postprocessing stages.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_parameter.hpp"
#include "materials/magnetization.hpp"
#include "materials/material.hpp"
#include "mesh/geometry2d.hpp"
#include "mesh/geometry3d.hpp"
#include "postproc/force_spec.hpp"
#include "postproc/probe_spec.hpp"
#include "postproc/section_spec.hpp"
#include "solver/newton.hpp"

namespace magfem {

struct RegionSpec {
  std::string name;
  const Material* material = nullptr; // resolved: case materials or the bundled library
  // A magnet region at its own `temperature_C` or with its own `HcJ_kApm`: its material
  // (B_r and knee at that temperature); `material` then points here.
  std::shared_ptr<const Material> own_material;
  Magnetization magnetization;
  double current_density = 0;    // A/m^2 along +z (planar) or +phi (axisymmetric)
  double ampere_turns = 0;       // if non-zero, J = ampere_turns / meshed area of the region
  double turns = 0, current = 0; // when given as turns and current (A); ampere_turns = N I
  std::string group;             // sweep group (--move axisymmetric, --rotate planar)
  int line = 0;                  // line of the region in the case file

  bool carries_current() const { return current_density != 0 || ampere_turns != 0; }
};

// The case's fields; CaseSpec below adds the copy that keeps its regions' materials its own.
struct CaseFields {
  std::string file;
  int dimension = 2;
  std::string unit_name = "mm";
  double length_unit = 1e-3; // metres per case length unit
  std::map<std::string, Material> materials;
  std::vector<RegionSpec> regions; // parallel to geometry2d.parts or geometry3d.parts
  Geometry2D geometry2d;           // dimension 2
  Geometry3D geometry3d;           // dimension 3
  int order = 2;
  NewtonOptions newton;
  std::vector<ProbeSpec> probes;
  std::vector<ForceSpec> forces;
  std::vector<SectionSpec> sections; // flux through plane (3D) or line (2D) sections
  bool write_vtu = true;
  bool write_revolved_vtu = false; // axisymmetric: also solution_revolved.vtu (3D)
  double stack_length = 0;         // metres; 0 = report per unit length
  int boundary_line = 0;
  std::vector<int> coil_lines;           // parallel to geometry3d.coils
  bool coil_inductance = true;           // 3D: the inductance matrix (one extra solve per coil)
  std::vector<CaseParameter> parameters; // the `parameters:` section, resolved (file order)
  AdaptSpec adapt;                       // `adapt:` (adaptive refinement; off by default)

  // `dimension: axi`: a 2D case in the r-z half plane (geometry2d.symmetry says so).
  bool axisymmetric() const {
    return dimension == 2 && geometry2d.symmetry == Symmetry2D::axisymmetric;
  }
};

// A region's `material` may point into its case's `materials`; a copy points into its own
// copy of them, so that it outlives the case it was copied from (an adaptive pass's case
// with new mesh sizes, a sweep position's). A move keeps the map's nodes, and so the pointers.
struct CaseSpec : CaseFields {
  CaseSpec() = default;
  CaseSpec(const CaseSpec& other) : CaseFields(other) { own_materials_of(other); }
  CaseSpec(CaseSpec&&) = default;
  CaseSpec& operator=(const CaseSpec& other) {
    if (this != &other) {
      CaseFields::operator=(other);
      own_materials_of(other);
    }
    return *this;
  }
  CaseSpec& operator=(CaseSpec&&) = default;

private:
  void own_materials_of(const CaseSpec& other) {
    for (auto& region : regions)
      for (const auto& [name, material] : other.materials)
        if (region.material == &material)
          region.material = &materials.at(name);
  }
};

// Reads and validates a case file. Every problem is an InputError naming file, line, field.
// `overrides` replace parameter values (case_parameter.hpp) before anything is read.
CaseSpec read_case(const std::string& path, const ParameterOverrides& overrides = {});
// The same from the file's text; `name` stands for the file in messages (tests, fuzzing).
CaseSpec read_case_text(const std::string& text, const std::string& name,
                        const ParameterOverrides& overrides = {});

} // namespace magfem
