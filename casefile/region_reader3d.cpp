// Regions of a 3D case: spherical segments and segment arrays (with the thesis's
// magnetization patterns), cylinders and radial cylinder arrays on a sphere, boxes, CAD parts
// (closed STL surfaces); rigid placement and groups.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include <Eigen/Geometry>

#include "casefile/case_spec.hpp"
#include "casefile/reader_helpers.hpp"
#include "core/constants.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/stl_reader3d.hpp"

namespace magfem {
namespace {

const std::vector<std::string> common_keys = {"name",          "shape",         "material",
                                              "magnetization", "placement",     "group",
                                              "mesh_size",     "temperature_C", "HcJ_kApm"};

std::vector<std::string> keys_with(std::initializer_list<const char*> extra) {
  std::vector<std::string> k = common_keys;
  k.insert(k.end(), extra.begin(), extra.end());
  return k;
}

// Rotation taking +z to `axis` (shortest arc).
Mat3 rotation_z_to(const Vec3& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
}

// placement: {translate: [x, y, z], rotate: {axis: [ax, ay, az], angle: deg}}: the local frame
// is rotated about its origin, then translated.
Placement read_placement(const YamlNode& p, double s) {
  p.allow_keys({"translate", "rotate"});
  Placement out;
  if (p.has("rotate")) {
    const auto r = p.at("rotate");
    r.allow_keys({"axis", "angle"});
    out.rotation =
        Eigen::AngleAxisd(r.at("angle").as_double() * deg_to_rad, read_direction3(r.at("axis")))
            .toRotationMatrix();
  }
  if (p.has("translate"))
    out.translation = read_point3(p.at("translate"), s);
  return out;
}

// magnetization: {type: parallel, direction: [x, y, z]} | {type: axial} (local +z) |
// {type: radial, center: [x, y, z]}, each with optional sign. Directions and centres are in
// the part's local frame and move with its placement.
Magnetization read_magnetization(const YamlNode& m, double s, const Placement& place) {
  m.allow_keys({"type", "direction", "center", "sign"});
  Magnetization out;
  out.sign = m.get_double("sign", 1.0);
  if (out.sign != 1.0 && out.sign != -1.0)
    m.at("sign").fail("sign must be 1 or -1");
  const std::string type = m.at("type").as_string();
  if (type == "parallel" || type == "axial") {
    out.pattern = Magnetization::Pattern::parallel;
    const Vec3 local = type == "axial" ? Vec3::UnitZ() : read_direction3(m.at("direction"));
    out.direction = place.rotation * local;
  } else if (type == "radial") {
    out.pattern = Magnetization::Pattern::radial;
    const Vec3 c = m.has("center") ? read_point3(m.at("center"), s) : Vec3::Zero();
    out.center = place.to_global(c);
  } else {
    m.at("type").fail("unknown magnetization type '" + type + "' (parallel, axial, radial)");
  }
  return out;
}

SphericalSegment read_segment(const YamlNode& r, double s) {
  SphericalSegment g;
  g.r_inner = r.has("r_inner") ? r.at("r_inner").as_non_negative() * s : 0.0;
  g.r_outer = r.at("r_outer").as_positive() * s;
  if (g.r_inner >= g.r_outer)
    r.at("r_inner").fail("r_inner must be smaller than r_outer");
  std::tie(g.theta_min, g.theta_max) =
      r.has("theta") ? read_angle_range(r.at("theta"), 0, 180) : std::pair{0.0, pi};
  std::tie(g.phi_min, g.phi_max) =
      r.has("phi") ? read_angle_range(r.at("phi"), -360, 360) : std::pair{0.0, 2 * pi};
  if (g.phi_max - g.phi_min > 2 * pi + 1e-12)
    r.at("phi").fail("the phi range exceeds 360 degrees");
  return g;
}

// shape: surface, file: part.stl (relative to the case file), file_unit: mm (STL files carry
// no unit; CAD systems export millimetres by default).
TriangleSurface read_surface(const YamlNode& r) {
  const YamlNode file = r.at("file");
  const std::filesystem::path given(file.as_string());
  const std::filesystem::path path =
      given.is_absolute() ? given : std::filesystem::path(r.file()).parent_path() / given;
  const double unit = r.has("file_unit") ? unit_scale(r.at("file_unit")) : 1e-3;
  try {
    TriangleSurface surface = read_stl_surface(path.string(), unit);
    surface.file = given.string();
    return surface;
  } catch (const MeshError& e) {
    file.fail(e.reason);
  }
}

struct Reader3D {
  CaseSpec& c;
  const MaterialLibrary& lib;
  double s;

  void add(const YamlNode& r, Part3D part, RegionSpec spec) {
    if (r.has("mesh_size"))
      part.max_size = r.at("mesh_size").as_positive() * s;
    if (r.has("group"))
      part.group = r.at("group").as_string();
    part.air =
        spec.material && spec.material->kind == MaterialKind::linear && spec.material->mu_r == 1.0;
    c.geometry3d.parts.push_back(std::move(part));
    c.regions.push_back(std::move(spec));
  }

  RegionSpec base_spec(const YamlNode& r, const std::string& name) {
    RegionSpec spec;
    spec.name = name;
    spec.line = r.line();
    read_region_material(r, c, lib, spec);
    return spec;
  }

  void single(const YamlNode& r, const std::string& name, Shape3D shape) {
    const Placement place = r.has("placement") ? read_placement(r.at("placement"), s) : Placement{};
    RegionSpec spec = base_spec(r, name);
    if (r.has("magnetization"))
      spec.magnetization = read_magnetization(r.at("magnetization"), s, place);
    add(r, Part3D{name, std::move(shape), place, 0, ""}, spec);
  }

  void segment_array(const YamlNode& r, const std::string& name);
  void cylinder_array(const YamlNode& r, const std::string& name);
};

// P_theta x P_phi segments over [theta range] x [phi range]. pattern:
//   {type: parallel_alternating, convention: centre|edge}: thesis eqs. 3.112-3.114, direction
//     angles at the segment's centre (theta) and its centre or start edge (phi), sign
//     (-1)^(p_theta + p_phi) (p counted from 1);
//   {type: radial_alternating}: eq. 3.116, +-e_rho with the same signs;
//   {type: parallel, direction: [x,y,z]} / {type: radial}: one direction / outward for all;
//   {type: per_segment, directions: [[x,y,z], ...]}: p_theta-major list of P_theta*P_phi.
// An optional `sign: -1` flips the whole pattern. Parts are named <name>_<p_theta>_<p_phi>.
// `cut_phi: [min, max]` then cuts the laid-out array to that phi range: segments keep their
// index, sign and direction (those of the uncut segment) and those wholly outside are dropped,
// so "an array cut in half" (the thesis's hemispherical actuator array, half-size magnets at
// the cut) is written as the whole array and the cut.
// `cell_fraction: f` (0 < f <= 1, default 1) shrinks every segment about its cell's centre to
// f of the cell's theta and phi extent before the cut, leaving gaps of (1 - f) of a cell
// between neighbours: the thesis's segmented back-iron (sec. 5.4), xi / tau_m of each magnet's
// cell behind it. Shrinking before the cut keeps a segment behind each half-size magnet at the
// cut where the whole cell's segment would be.
void Reader3D::segment_array(const YamlNode& r, const std::string& name) {
  r.allow_keys(keys_with({"r_inner", "r_outer", "theta", "phi", "p_theta", "p_phi", "pattern",
                          "cut_phi", "cell_fraction"}));
  const SphericalSegment whole = read_segment(r, s);
  const double fraction = r.has("cell_fraction") ? r.at("cell_fraction").as_positive() : 1.0;
  if (fraction > 1)
    r.at("cell_fraction").fail("cell_fraction must be at most 1 (1 = segments fill their cells)");
  std::optional<std::pair<double, double>> cut;
  if (r.has("cut_phi")) {
    cut = read_angle_range(r.at("cut_phi"), -360, 360);
    if (cut->second <= whole.phi_min || cut->first >= whole.phi_max)
      r.at("cut_phi").fail("the cut leaves nothing of the array's phi range");
  }
  const int nt = r.at("p_theta").as_int(), np = r.at("p_phi").as_int();
  if (nt < 1)
    r.at("p_theta").fail("must be at least 1");
  if (np < 1)
    r.at("p_phi").fail("must be at least 1");
  const Placement place = r.has("placement") ? read_placement(r.at("placement"), s) : Placement{};
  RegionSpec proto = base_spec(r, name);
  std::string type = "none";
  std::optional<YamlNode> pat = r.find("pattern");
  if (proto.material->is_magnet()) {
    if (!pat)
      r.fail("a magnet segment array needs a pattern");
    pat->allow_keys({"type", "convention", "direction", "directions", "sign"});
    type = pat->at("type").as_string();
  }
  const double global_sign = pat ? pat->get_double("sign", 1.0) : 1.0;
  if (global_sign != 1.0 && global_sign != -1.0)
    pat->at("sign").fail("sign must be 1 or -1");
  const bool edge = pat && pat->get_string("convention", "centre") == "edge";
  if (pat && pat->has("convention") && !edge && pat->at("convention").as_string() != "centre")
    pat->at("convention").fail("convention must be centre or edge");
  std::vector<YamlNode> per_segment;
  if (type == "per_segment") {
    per_segment = pat->at("directions").items();
    if (static_cast<int>(per_segment.size()) != nt * np)
      pat->at("directions")
          .fail("expected p_theta * p_phi = " + std::to_string(nt * np) + " directions");
  } else if (pat && type != "parallel_alternating" && type != "radial_alternating" &&
             type != "parallel" && type != "radial") {
    pat->at("type").fail(
        "unknown pattern '" + type +
        "' (parallel_alternating, radial_alternating, parallel, radial, per_segment)");
  }
  const double dt = (whole.theta_max - whole.theta_min) / nt;
  const double dp = (whole.phi_max - whole.phi_min) / np;
  int n_added = 0;
  for (int it = 1; it <= nt; ++it)
    for (int ip = 1; ip <= np; ++ip) {
      SphericalSegment seg = whole;
      seg.theta_min = whole.theta_min + (it - 1) * dt;
      seg.theta_max = whole.theta_min + it * dt;
      seg.phi_min = whole.phi_min + (ip - 1) * dp;
      seg.phi_max = whole.phi_min + ip * dp;
      RegionSpec spec = proto;
      spec.name = name + "_" + std::to_string(it) + "_" + std::to_string(ip);
      Magnetization& m = spec.magnetization;
      const double alternating = ((it + ip) % 2 == 0) ? 1.0 : -1.0;
      if (type == "parallel_alternating") {
        const double lt = 0.5 * (seg.theta_min + seg.theta_max);
        const double lp = edge ? seg.phi_min : 0.5 * (seg.phi_min + seg.phi_max);
        m.pattern = Magnetization::Pattern::parallel;
        m.direction = place.rotation *
                      Vec3(std::sin(lt) * std::cos(lp), std::sin(lt) * std::sin(lp), std::cos(lt));
        m.sign = alternating * global_sign;
      } else if (type == "radial_alternating" || type == "radial") {
        m.pattern = Magnetization::Pattern::radial;
        m.center = place.translation;
        m.sign = (type == "radial" ? 1.0 : alternating) * global_sign;
      } else if (type == "parallel") {
        m.pattern = Magnetization::Pattern::parallel;
        m.direction = place.rotation * read_direction3(pat->at("direction"));
        m.sign = global_sign;
      } else if (type == "per_segment") {
        m.pattern = Magnetization::Pattern::parallel;
        m.direction = place.rotation * read_direction3(per_segment[(it - 1) * np + (ip - 1)]);
        m.sign = global_sign;
      }
      // After the magnetization: the pattern's angles are the whole cell's.
      const double theta_margin = 0.5 * (1 - fraction) * dt, phi_margin = 0.5 * (1 - fraction) * dp;
      seg.theta_min += theta_margin;
      seg.theta_max -= theta_margin;
      seg.phi_min += phi_margin;
      seg.phi_max -= phi_margin;
      if (cut) {
        // Cuts thinner than round-off would only make slivers.
        seg.phi_min = std::max(seg.phi_min, cut->first);
        seg.phi_max = std::min(seg.phi_max, cut->second);
        if (seg.phi_max - seg.phi_min < 1e-9)
          continue;
      }
      add(r, Part3D{spec.name, seg, place, 0, ""}, spec);
      ++n_added;
    }
  if (n_added == 0)
    r.at("cut_phi").fail("the cut leaves none of the (shrunk) segments");
}

// Cylinders standing radially on a sphere (the thesis's segmented outer magnet): bases at
// distance `base_radius` from the local origin, arranged in rings of constant theta with
// centre spacing `pitch` (arc length at the base sphere), over the theta range. Each
// cylinder's axis points away from the centre; magnetization {type: axial|radial, sign}.
void Reader3D::cylinder_array(const YamlNode& r, const std::string& name) {
  r.allow_keys(keys_with({"r_outer", "height", "base_radius", "pitch", "theta"}));
  const double rc = r.at("r_outer").as_positive() * s, h = r.at("height").as_positive() * s;
  const double rb = r.at("base_radius").as_positive() * s, pitch = r.at("pitch").as_positive() * s;
  if (pitch < 2 * rc)
    r.at("pitch").fail("pitch must be at least the cylinder diameter");
  const auto [t0, t1] =
      r.has("theta") ? read_angle_range(r.at("theta"), 0, 180) : std::pair{0.0, 0.5 * pi};
  const Placement place = r.has("placement") ? read_placement(r.at("placement"), s) : Placement{};
  RegionSpec proto = base_spec(r, name);
  double sign = 1.0;
  if (r.has("magnetization")) {
    const auto m = r.at("magnetization");
    m.allow_keys({"type", "sign"});
    const std::string t = m.at("type").as_string();
    if (t != "axial" && t != "radial")
      m.at("type").fail("cylinder arrays are magnetized axial (= radial)");
    sign = m.get_double("sign", 1.0);
    if (sign != 1.0 && sign != -1.0)
      m.at("sign").fail("sign must be 1 or -1");
  }
  const double dtheta = pitch / rb;
  int index = 0;
  auto place_one = [&](double theta, double phi) {
    const Vec3 axis(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                    std::cos(theta));
    Placement local{rotation_z_to(axis), rb * axis};
    Placement global{place.rotation * local.rotation, place.to_global(local.translation)};
    RegionSpec spec = proto;
    spec.name = name + "_" + std::to_string(++index);
    if (proto.material->is_magnet()) {
      spec.magnetization.pattern = Magnetization::Pattern::parallel;
      spec.magnetization.direction = global.rotation * Vec3::UnitZ();
      spec.magnetization.sign = sign;
    }
    add(r, Part3D{spec.name, Cylinder{0, rc, h}, global, 0, ""}, spec);
  };
  double theta = t0;
  if (t0 == 0) {
    place_one(0, 0);
    theta = dtheta;
  } else {
    theta = t0 + 0.5 * dtheta;
  }
  for (; theta <= t1 - 0.5 * dtheta + 1e-12; theta += dtheta) {
    const int n = static_cast<int>(std::floor(2 * pi * rb * std::sin(theta) / pitch));
    for (int k = 0; k < n; ++k)
      place_one(theta, 2 * pi * k / n);
  }
  if (index == 0)
    r.fail("the cylinder array is empty: pitch too large for the theta range");
}

} // namespace

void read_regions_3d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib) {
  Reader3D reader{c, lib, c.length_unit};
  const double s = c.length_unit;
  std::set<std::string> names;
  for (const auto& r : regions.items()) {
    const std::string name = r.at("name").as_string();
    if (!names.insert(name).second)
      r.at("name").fail("duplicate region name '" + name + "'");
    const std::string shape = r.at("shape").as_string();
    if (shape == "spherical_segment") {
      r.allow_keys(keys_with({"r_inner", "r_outer", "theta", "phi"}));
      reader.single(r, name, read_segment(r, s));
    } else if (shape == "cylinder") {
      r.allow_keys(keys_with({"r_inner", "r_outer", "height"}));
      Cylinder cyl{r.has("r_inner") ? r.at("r_inner").as_non_negative() * s : 0.0,
                   r.at("r_outer").as_positive() * s, r.at("height").as_positive() * s};
      if (cyl.r_inner >= cyl.r_outer)
        r.at("r_inner").fail("r_inner must be smaller than r_outer");
      reader.single(r, name, cyl);
    } else if (shape == "box") {
      r.allow_keys(keys_with({"size"}));
      const Vec3 size = read_point3(r.at("size"), s);
      if (size.minCoeff() <= 0)
        r.at("size").fail("box sizes must be positive");
      reader.single(r, name, Box{size});
    } else if (shape == "surface") {
      r.allow_keys(keys_with({"file", "file_unit"}));
      reader.single(r, name, read_surface(r));
    } else if (shape == "segment_array") {
      reader.segment_array(r, name);
    } else if (shape == "cylinder_array") {
      reader.cylinder_array(r, name);
    } else {
      r.at("shape").fail(
          "unknown shape '" + shape +
          "' (spherical_segment, segment_array, cylinder, cylinder_array, box, surface)");
    }
  }
}

} // namespace magfem
