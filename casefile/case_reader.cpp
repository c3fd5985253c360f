// Case-file reader: YAML -> CaseSpec. Units are converted here and only here.
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "casefile/adapt_reader.hpp"
#include "casefile/case_parameters.hpp"
#include "casefile/case_spec.hpp"
#include "casefile/force_reader.hpp"
#include "casefile/reader_helpers.hpp"
#include "casefile/section_reader.hpp"
#include "core/constants.hpp"
#include "core/yaml_node.hpp"
#include "materials/material_library.hpp"
#include "materials/material_parser.hpp"

namespace magfem {
namespace {

// Outer boundary, common to both dimensions: a circle (2D) or sphere (3D) about the origin.
// `symmetry: [{plane: z, field: normal}, ...]` (mesh/symmetry_plane3d.hpp; 2D and
// axisymmetric: mesh/symmetry_plane2d.hpp).
void read_symmetry(const YamlNode& list, CaseSpec& c) {
  if (!list.is_sequence())
    list.fail("expected a list of planes, e.g. [{plane: z, field: normal}]");
  std::vector<SymmetryPlane3D> planes;
  for (const YamlNode& item : list.items()) {
    item.allow_keys({"plane", "field"});
    const std::string plane = item.at("plane").as_string();
    const std::string field = item.at("field").as_string();
    SymmetryPlane3D p;
    if (plane != "x" && plane != "y" && plane != "z")
      item.at("plane").fail("unknown symmetry plane '" + plane +
                            "' (x, y or z: the plane where that coordinate is 0)");
    p.axis = plane[0] - 'x';
    if (c.axisymmetric() && plane != "z")
      item.at("plane").fail("an axisymmetric case has one symmetry plane, z (z = 0); it is "
                            "symmetric about every plane through the axis already");
    if (c.dimension == 2 && !c.axisymmetric() && plane == "z")
      item.at("plane").fail("a planar case is its own image about z = 0 already; its planes "
                            "are x and y");
    if (field != "normal" && field != "parallel")
      item.at("field").fail("unknown field condition '" + field +
                            "' (normal: n x H = 0, field lines cross the plane; parallel: "
                            "B . n = 0, field lines run along it)");
    p.field = field == "normal" ? SymmetryField::normal : SymmetryField::parallel;
    for (const SymmetryPlane3D& q : planes)
      if (q.axis == p.axis)
        item.at("plane").fail("plane " + plane + " is listed twice");
    planes.push_back(p);
  }
  if (c.dimension == 3) {
    c.geometry3d.symmetry = planes;
    return;
  }
  for (const SymmetryPlane3D& p : planes) // axisymmetric: z = 0 is the r-z plane's y = 0
    c.geometry2d.planes.push_back({c.axisymmetric() ? 1 : p.axis, p.field});
}

void read_boundary(const YamlNode& b, double s, CaseSpec& c) {
  b.allow_keys({"type", "radius", "shell_ratio", "symmetry"});
  if (const auto sym = b.find("symmetry"))
    read_symmetry(*sym, c);
  c.boundary_line = b.line();
  const std::string type = b.at("type").as_string();
  const double radius = b.at("radius").as_positive() * s;
  const double ratio = b.get_positive("shell_ratio", 1.5);
  if (ratio <= 1.05)
    b.at("shell_ratio").fail("shell_ratio must exceed 1.05");
  if (type != "open" && type != "dirichlet" && type != "neumann")
    b.at("type").fail("unknown boundary type '" + type + "' (open, dirichlet, neumann)");
  c.geometry2d.outer = {type == "open"        ? OuterKind::open
                        : type == "dirichlet" ? OuterKind::dirichlet
                                              : OuterKind::neumann,
                        radius, ratio};
  c.geometry3d.outer = {type == "open"        ? OuterKind3D::open
                        : type == "dirichlet" ? OuterKind3D::dirichlet
                                              : OuterKind3D::neumann,
                        radius, ratio};
}

void read_mesh_options_2d(const YamlNode& m, double s, CaseSpec& c) {
  m.allow_keys({"size", "chord_tolerance", "min_angle", "gap_layers", "scale"});
  auto& o = c.geometry2d.options;
  o.default_size = m.at("size").as_positive() * s;
  o.chord_tolerance = m.has("chord_tolerance") ? m.at("chord_tolerance").as_positive() * s : 1e-5;
  o.min_angle_deg = m.get_positive("min_angle", 28.0);
  if (o.min_angle_deg > 33)
    m.at("min_angle").fail("min_angle above 33 degrees may not terminate");
  o.gap_layers = m.get_int("gap_layers", 3);
  if (o.gap_layers < 1)
    m.at("gap_layers").fail("gap_layers must be at least 1");
  o.size_scale = m.get_positive("scale", 1.0);
}

void read_mesh_options_3d(const YamlNode& m, double s, CaseSpec& c) {
  m.allow_keys({"size", "chord_tolerance", "radius_edge", "gap_layers", "scale", "probe_size",
                "shell_size"});
  auto& o = c.geometry3d.options;
  o.default_size = m.at("size").as_positive() * s;
  o.chord_tolerance = m.has("chord_tolerance") ? m.at("chord_tolerance").as_positive() * s : 5e-5;
  o.radius_edge_ratio = m.get_positive("radius_edge", 1.6);
  if (o.radius_edge_ratio < 1.1)
    m.at("radius_edge").fail("radius_edge below 1.1 may not terminate");
  o.gap_layers = m.get_int("gap_layers", 3);
  if (o.gap_layers < 1)
    m.at("gap_layers").fail("gap_layers must be at least 1");
  o.size_scale = m.get_positive("scale", 1.0);
  if (m.has("probe_size"))
    o.probe_size = m.at("probe_size").as_positive() * s;
  if (m.has("shell_size")) {
    o.shell_size = m.at("shell_size").as_positive() * s;
    if (c.geometry3d.outer.kind != OuterKind3D::open) // read_boundary ran first
      m.at("shell_size").fail("shell_size needs boundary type open (there is no shell)");
  }
}

// The Krylov solver's settings (CG's preconditioner, its tolerance and iteration limit, PETSc
// options). A preconditioner or PETSc options mean CG, so they contradict `cholmod`.
void read_linear_solver(const YamlNode& n, LinearSolverOptions& o) {
  const std::string pre = n.get_string("preconditioner", "auto");
  if (pre == "auto")
    o.preconditioner = PreconditionerKind::automatic;
  else if (pre == "ichol")
    o.preconditioner = PreconditionerKind::ichol;
  else if (pre == "amg" || pre == "boomeramg")
    o.preconditioner = PreconditionerKind::boomeramg;
  else if (pre == "gamg")
    o.preconditioner = PreconditionerKind::gamg;
  else if (pre == "pmg")
    o.preconditioner = PreconditionerKind::pmg;
  else
    n.at("preconditioner").fail("preconditioner must be auto, ichol, pmg, amg, boomeramg or gamg");
  o.petsc_options = n.get_string("petsc_options", "");
  if (o.kind == LinearSolverKind::cholmod && (pre != "auto" || !o.petsc_options.empty()))
    n.at(pre != "auto" ? "preconditioner" : "petsc_options")
        .fail("a preconditioner and PETSc options are for linear_solver: cg, not cholmod");
  if (pre == "ichol" && !o.petsc_options.empty())
    n.at("petsc_options")
        .fail("petsc_options need a PETSc preconditioner (auto, pmg, amg or gamg)");
  if (!o.petsc_options.empty())
    if (const std::string why = petsc_options_problem(o); !why.empty())
      n.at("petsc_options").fail(why);
  if (n.has("linear_tolerance")) {
    o.cg_tolerance = n.at("linear_tolerance").as_positive();
    if (o.cg_tolerance >= 1)
      n.at("linear_tolerance").fail("linear_tolerance must be below 1");
  }
  o.cg_max_iterations = n.get_int("linear_max_iterations", o.cg_max_iterations);
  if (o.cg_max_iterations < 1)
    n.at("linear_max_iterations").fail("must be at least 1");
}

void read_solver(const YamlNode& n, CaseSpec& c) {
  n.allow_keys({"order", "method", "tolerance", "max_iterations", "linear_solver", "preconditioner",
                "petsc_options", "linear_tolerance", "linear_max_iterations"});
  c.order = n.get_int("order", 2);
  if (c.order != 1 && c.order != 2)
    n.at("order").fail("order must be 1 or 2");
  const std::string method = n.get_string("method", "newton");
  if (method == "newton")
    c.newton.method = TangentKind::newton;
  else if (method == "picard")
    c.newton.method = TangentKind::picard;
  else
    n.at("method").fail("method must be newton or picard");
  if (n.has("tolerance")) {
    c.newton.residual_tol = n.at("tolerance").as_positive();
    c.newton.update_tol = c.newton.residual_tol;
  }
  c.newton.max_iterations = n.get_int("max_iterations", c.newton.max_iterations);
  if (c.newton.max_iterations < 1)
    n.at("max_iterations").fail("must be at least 1");
  const std::string ls = n.get_string("linear_solver", "auto");
  if (ls == "auto")
    c.newton.linear.kind = LinearSolverKind::automatic;
  else if (ls == "cholmod")
    c.newton.linear.kind = LinearSolverKind::cholmod;
  else if (ls == "cg")
    c.newton.linear.kind = LinearSolverKind::cg;
  else
    n.at("linear_solver").fail("linear_solver must be auto, cholmod or cg");
  read_linear_solver(n, c.newton.linear);
}

[[noreturn]] void outside(const YamlNode& p, const ProbeSpec& probe, double domain, double s) {
  p.fail("probe '" + probe.name + "' leaves the domain (radius " + std::to_string(domain / s) +
         ")");
}

void check_half_plane(const YamlNode& p, double r, const std::string& what) {
  if (r < 0)
    p.fail("the " + what + " has r < 0: axisymmetric cases live in the half plane r >= 0");
}

void read_line_probe(const YamlNode& p, double s, int dim, bool axi, double domain,
                     ProbeSpec& probe) {
  p.allow_keys({"name", "type", "start", "end", "points"});
  probe.kind = ProbeSpec::Kind::line;
  if (dim == 2) {
    const Eigen::Vector2d a = read_point2(p.at("start"), s), b = read_point2(p.at("end"), s);
    if (axi) {
      check_half_plane(p.at("start"), a.x(), "start point");
      check_half_plane(p.at("end"), b.x(), "end point");
    }
    probe.start = {a.x(), a.y(), 0};
    probe.end = {b.x(), b.y(), 0};
  } else {
    probe.start = read_point3(p.at("start"), s);
    probe.end = read_point3(p.at("end"), s);
  }
  probe.points = p.get_int("points", 101);
  // The domain is a disk or ball, hence convex: both ends inside means the whole line is.
  if (probe.start.norm() > domain || probe.end.norm() > domain)
    outside(p, probe, domain, s);
}

void read_circle_probe(const YamlNode& p, double s, bool axi, double domain, ProbeSpec& probe) {
  p.allow_keys({"name", "type", "center", "radius", "points", "angle_start", "angle_end"});
  probe.kind = ProbeSpec::Kind::circle;
  const Eigen::Vector2d ctr =
      p.has("center") ? read_point2(p.at("center"), s) : Eigen::Vector2d::Zero();
  probe.center = {ctr.x(), ctr.y(), 0};
  probe.radius = p.at("radius").as_positive() * s;
  probe.points = p.get_int("points", 360);
  probe.angle_start = p.get_double("angle_start", 0.0) * deg_to_rad;
  probe.angle_end = p.get_double("angle_end", 360.0) * deg_to_rad;
  if (!(probe.angle_end > probe.angle_start))
    p.at("angle_end").fail("angle_end must exceed angle_start");
  // An arc in the r-z plane must stay at r >= 0: check its leftmost point.
  if (axi) {
    const double a0 = probe.angle_start, a1 = probe.angle_end;
    const double left = pi + 2 * pi * std::ceil((a0 - pi) / (2 * pi)); // first angle pi >= a0
    const double cos_min = left <= a1 ? -1.0 : std::min(std::cos(a0), std::cos(a1));
    check_half_plane(p, ctr.x() + probe.radius * cos_min + 1e-12 * domain, "arc");
  }
  if (ctr.norm() + probe.radius > domain)
    outside(p, probe, domain, s);
}

// Sphere patch: theta and phi ranges in degrees, sampled with `step` degrees (both ends
// included) or with explicit theta_steps / phi_steps sample counts.
void read_sphere_probe(const YamlNode& p, double s, double domain, ProbeSpec& probe) {
  p.allow_keys(
      {"name", "type", "center", "radius", "theta", "phi", "step", "theta_steps", "phi_steps"});
  probe.kind = ProbeSpec::Kind::sphere;
  probe.center = p.has("center") ? read_point3(p.at("center"), s) : Eigen::Vector3d::Zero();
  probe.radius = p.at("radius").as_positive() * s;
  const auto [t0, t1] =
      p.has("theta") ? read_angle_range(p.at("theta"), 0, 180) : std::pair{0.0, pi};
  const auto [p0, p1] =
      p.has("phi") ? read_angle_range(p.at("phi"), -360, 360) : std::pair{0.0, 2 * pi};
  probe.theta_min = t0;
  probe.theta_max = t1;
  probe.phi_min = p0;
  probe.phi_max = p1;
  if (p.has("step")) {
    const double step = p.at("step").as_positive() * deg_to_rad;
    probe.theta_steps = static_cast<int>(std::lround((t1 - t0) / step)) + 1;
    probe.phi_steps = static_cast<int>(std::lround((p1 - p0) / step)) + 1;
  } else {
    probe.theta_steps = p.get_int("theta_steps", 46);
    probe.phi_steps = p.get_int("phi_steps", 46);
  }
  if (probe.theta_steps < 1 || probe.phi_steps < 1)
    p.fail("a sphere probe needs at least one sample");
  probe.points = probe.theta_steps * probe.phi_steps;
  if (probe.center.norm() + probe.radius > domain)
    outside(p, probe, domain, s);
}

void read_points_probe(const YamlNode& p, double s, double domain, ProbeSpec& probe) {
  p.allow_keys({"name", "type", "points"});
  probe.kind = ProbeSpec::Kind::points;
  for (const auto& pt : p.at("points").items()) {
    probe.point_list.push_back(read_point3(pt, s));
    if (probe.point_list.back().norm() > domain)
      outside(pt, probe, domain, s);
  }
  probe.points = static_cast<int>(probe.point_list.size());
}

// A u_steps x v_steps grid on a rectangle of a plane (`points: [n_u, n_v]`).
void read_plane_probe(const YamlNode& p, double s, double domain, ProbeSpec& probe) {
  p.allow_keys({"name", "type", "center", "normal", "u", "size", "points"});
  probe.kind = ProbeSpec::Kind::plane;
  probe.plane = read_plane_frame(p, s);
  probe.center = probe.plane.center;
  const Eigen::Vector2d size = read_size2(p.at("size"), s);
  probe.size_u = size.x();
  probe.size_v = size.y();
  const auto steps = p.at("points");
  if (!steps.is_sequence() || steps.size() != 2)
    steps.fail("points must be [n_u, n_v], the grid's sample counts along u and v");
  probe.u_steps = steps[0].as_int();
  probe.v_steps = steps[1].as_int();
  if (probe.u_steps < 1 || probe.v_steps < 1)
    steps.fail("a plane probe needs at least one sample along each side");
  probe.points = probe.u_steps * probe.v_steps;
  if (farthest_point(probe.plane, probe.size_u, probe.size_v) > domain)
    outside(p, probe, domain, s);
}

ProbeSpec read_probe(const YamlNode& p, const CaseSpec& c) {
  ProbeSpec probe;
  probe.line = p.line();
  probe.name = p.at("name").as_string();
  static const std::regex safe("[A-Za-z0-9_.-]+");
  if (!std::regex_match(probe.name, safe))
    p.at("name").fail("probe names become file names: use letters, digits, '_', '-', '.'");
  const std::string type = p.at("type").as_string();
  const double s = c.length_unit;
  const double domain = c.dimension == 2 ? c.geometry2d.outer.radius : c.geometry3d.outer.radius;
  if (type == "line")
    read_line_probe(p, s, c.dimension, c.axisymmetric(), domain, probe);
  else if (type == "circle" && c.dimension == 2)
    read_circle_probe(p, s, c.axisymmetric(), domain, probe);
  else if (type == "sphere" && c.dimension == 3)
    read_sphere_probe(p, s, domain, probe);
  else if (type == "points" && c.dimension == 3)
    read_points_probe(p, s, domain, probe);
  else if (type == "plane" && c.dimension == 3)
    read_plane_probe(p, s, domain, probe);
  else
    p.at("type").fail("unknown probe type '" + type + "' for dimension " +
                      std::to_string(c.dimension) +
                      (c.dimension == 2 ? " (line, circle)" : " (line, sphere, points, plane)"));
  if (probe.points < 1)
    p.at("points").fail("points must be at least 1");
  return probe;
}

} // namespace

CaseSpec read_case(const std::string& path, const ParameterOverrides& overrides) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path, 0, "", "cannot open the file");
  std::stringstream text;
  text << in.rdbuf();
  return read_case_text(text.str(), path, overrides);
}

CaseSpec read_case_text(const std::string& text, const std::string& path,
                        const ParameterOverrides& overrides) {
  const YamlNode root = YamlNode::load_string(quote_expressions(text), path);
  root.allow_keys({"title", "description", "dimension", "unit", "parameters", "stack_length",
                   "materials", "regions", "coils", "boundary", "mesh", "solver", "probes",
                   "forces", "sections", "output", "adapt"});
  CaseSpec c;
  c.file = path;
  // Parameters first: every field below then reads plain numbers (the unit cannot be one).
  c.parameters =
      apply_parameters(root, overrides, root.has("unit") ? unit_scale(root.at("unit")) : 1e-3);
  // Read as text: '2d' should hear the choices, not "expected a number". The docs and the
  // messages call these cases axisymmetric, so that spelling is accepted beside `axi`.
  const std::string dim = root.has("dimension") ? root.at("dimension").as_string() : "2";
  if (dim == "axi" || dim == "axisymmetric") {
    c.dimension = 2;
    c.geometry2d.symmetry = Symmetry2D::axisymmetric;
  } else if (dim == "2" || dim == "3") {
    c.dimension = dim == "2" ? 2 : 3;
  } else {
    root.at("dimension").fail("dimension must be 2 | 3 | axi | axisymmetric (got '" + dim + "')");
  }
  const bool axi = c.axisymmetric();
  if (root.has("unit")) {
    c.unit_name = root.at("unit").as_string();
    c.length_unit = unit_scale(root.at("unit"));
  }
  const double s = c.length_unit;
  if (root.has("stack_length")) {
    if (c.dimension == 3 || axi)
      root.at("stack_length").fail("stack_length applies to planar 2D cases only");
    c.stack_length = root.at("stack_length").as_positive() * s;
  }
  const auto& lib = MaterialLibrary::bundled();
  if (root.has("materials"))
    c.materials = parse_materials(root.at("materials"), lib);

  read_boundary(root.at("boundary"), s, c);
  if (c.dimension == 2)
    read_mesh_options_2d(root.at("mesh"), s, c);
  else
    read_mesh_options_3d(root.at("mesh"), s, c);
  const auto regions = root.at("regions");
  if (regions.size() == 0)
    regions.fail("at least one region is needed");
  if (c.dimension == 2)
    read_regions_2d(regions, c, lib);
  else
    read_regions_3d(regions, c, lib);
  if (root.has("coils"))
    read_coils_3d(root.at("coils"), c);

  if (root.has("solver"))
    read_solver(root.at("solver"), c);
  if (root.has("probes")) {
    std::set<std::string> probe_names;
    for (const auto& p : root.at("probes").items()) {
      c.probes.push_back(read_probe(p, c));
      if (!probe_names.insert(c.probes.back().name).second)
        p.at("name").fail("duplicate probe name '" + c.probes.back().name + "'");
    }
  }
  if (root.has("forces"))
    read_forces(root.at("forces"), c);
  if (root.has("sections"))
    read_sections(root.at("sections"), c);
  if (root.has("adapt"))
    read_adapt(root.at("adapt"), c);
  if (root.has("output")) {
    const auto o = root.at("output");
    o.allow_keys({"vtu", "inductance", "revolved_vtu"});
    c.write_vtu = o.get_bool("vtu", true);
    c.write_revolved_vtu = o.get_bool("revolved_vtu", false);
    if (c.write_revolved_vtu && !c.axisymmetric())
      o.at("revolved_vtu").fail("revolved_vtu applies to axisymmetric cases (dimension: axi)");
    c.coil_inductance = o.get_bool("inductance", true);
  }
  return c;
}

} // namespace magfem
