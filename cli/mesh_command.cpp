#include "cli/mesh_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "casefile/cli_number.hpp"
#include "core/output_stage.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/tet_plane_cut.hpp"
#include "postproc/vtu_cell_names.hpp"
#include "postproc/vtu_writer.hpp"
#include "solver/dof_map2d.hpp"
#include "solver/dof_map3d.hpp"
#include "studies/gnuplot.hpp"

namespace magfem {

namespace {

struct MeshOptions {
  std::string out_dir;
  RunOverrides overrides;
  ParameterOverrides parameters;
  char plane = 'y'; // 3D picture: the cut normal to this axis through the origin
};

const OptionTable<MeshOptions>& mesh_option_table() {
  using O = MeshOptions;
  using S = const std::string&;
  static const auto table =
      OptionTable<O>("mesh")
          .value("--out", "DIR", [](O& o, S, S v) { o.out_dir = v; })
          .value("--order", "1|2", [](O& o, S, S v) { o.overrides.order = parse_cli_order(v); })
          .value("--mesh-scale", "S",
                 [](O& o, S, S v) { o.overrides.mesh_scale = parse_cli_mesh_scale(v); })
          .value("--plane", "x|y|z",
                 [](O& o, S opt, S v) {
                   if (v != "x" && v != "y" && v != "z")
                     throw_option_error(opt, "must be x, y or z, got '" + v + "'");
                   o.plane = v[0];
                 })
          .value("--param", "NAME=VALUE",
                 [](O& o, S, S v) { parse_cli_parameter(v, o.parameters); });
  return table;
}

// What one region of the mesh holds: elements, measure (m^2 or m^3) and element edges (m).
struct RegionStats {
  std::size_t elements = 0;
  double measure = 0, edge_min = 1e300, edge_max = 0;

  void add(double measure_of_element, double shortest, double longest) {
    ++elements;
    measure += measure_of_element;
    edge_min = std::min(edge_min, shortest);
    edge_max = std::max(edge_max, longest);
  }
};

// Elements by region id (case region index, -1 background air, -2 exterior shell).
using RegionTable = std::map<int, RegionStats>;

template <class Point, std::size_t N>
std::pair<double, double> edge_range(const std::vector<Point>& nodes, const std::array<int, N>& e) {
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) {
      const double l = (nodes[e[i]] - nodes[e[j]]).norm();
      lo = std::min(lo, l), hi = std::max(hi, l);
    }
  return {lo, hi};
}

RegionTable region_table(const Mesh2D& mesh, bool axisymmetric) {
  RegionTable table;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector2d a = mesh.nodes[tri[1]] - mesh.nodes[tri[0]],
                          b = mesh.nodes[tri[2]] - mesh.nodes[tri[0]];
    double measure = 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    if (axisymmetric) // the volume of revolution (Pappus): 2 pi r_centroid area
      measure *= 2 * 3.141592653589793 *
                 (mesh.nodes[tri[0]].x() + mesh.nodes[tri[1]].x() + mesh.nodes[tri[2]].x()) / 3;
    const auto [lo, hi] = edge_range(mesh.nodes, tri);
    if (mesh.triangle_part[t] != region_shell) // not physical coordinates
      table[mesh.triangle_part[t]].add(measure, lo, hi);
  }
  return table;
}

RegionTable region_table(const Mesh3D& mesh) {
  RegionTable table;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const auto& tet = mesh.tets[t];
    const Eigen::Vector3d& x0 = mesh.nodes[tet[0]];
    const double volume =
        std::abs(
            (mesh.nodes[tet[1]] - x0).cross(mesh.nodes[tet[2]] - x0).dot(mesh.nodes[tet[3]] - x0)) /
        6;
    const auto [lo, hi] = edge_range(mesh.nodes, tet);
    if (mesh.tet_part[t] != region_shell_3d) // not physical coordinates
      table[mesh.tet_part[t]].add(volume, lo, hi);
  }
  return table;
}

std::string region_name(const CaseSpec& spec, int id) {
  if (id >= 0 && id < static_cast<int>(spec.regions.size()))
    return spec.regions[static_cast<std::size_t>(id)].name;
  return "air";
}

nlohmann::ordered_json regions_json(const CaseSpec& spec, const RegionTable& table, bool volume) {
  auto out = nlohmann::ordered_json::array();
  for (const auto& [id, r] : table)
    out.push_back({{"name", region_name(spec, id)},
                   {"region_id", id},
                   {"elements", r.elements},
                   {volume ? "volume_m3" : "area_m2", r.measure},
                   {"edge_min_m", r.edge_min},
                   {"edge_max_m", r.edge_max}});
  return out;
}

void print_regions(const CaseSpec& spec, const RegionTable& table, const char* measure_unit) {
  std::printf("%-16s %10s %14s %12s %12s\n", "region", "elements", measure_unit, "edge_min_mm",
              "edge_max_mm");
  for (const auto& [id, r] : table)
    std::printf("%-16s %10zu %14.6g %12.4g %12.4g\n", region_name(spec, id).c_str(), r.elements,
                r.measure, 1e3 * r.edge_min, 1e3 * r.edge_max);
}

// A light colour per region (background air grey), cycling through a qualitative palette.
std::string region_colour(int id) {
  static const char* palette[] = {"#8dd3c7", "#fb8072", "#80b1d3", "#fdb462", "#b3de69",
                                  "#fccde5", "#bc80bd", "#ccebc5", "#ffed6f", "#bebada"};
  return id < 0 ? "#eeeeee" : palette[id % 10];
}

// Polygons (metres) by region id, drawn filled in their region's colour with black edges.
using PolygonsByRegion = std::map<int, std::vector<std::vector<Eigen::Vector2d>>>;

bool plot_polygons(const PolygonsByRegion& polygons, const CaseSpec& spec, const std::string& title,
                   const std::string& xlabel, const std::string& ylabel,
                   const std::filesystem::path& png, std::string& why) {
  if (!gnuplot_available(why))
    return false;
  const auto script = std::filesystem::path(png).replace_extension(".gp");
  std::vector<std::filesystem::path> data;
  std::ofstream g(script);
  g << "set terminal pngcairo size 1200,1000 noenhanced\nset output '" << png.string() << "'\n"
    << "set title \"" << gnuplot_title(title) << "\"\nset size ratio -1\n"
    << "set xlabel '" << xlabel << " (mm)'\nset ylabel '" << ylabel << " (mm)'\n"
    << "set key outside right top\nplot ";
  bool first = true;
  for (const auto& [id, list] : polygons) {
    data.push_back(
        std::filesystem::path(png).replace_extension(".region" + std::to_string(id + 2) + ".dat"));
    std::ofstream d(data.back());
    for (const auto& p : list) {
      for (std::size_t k = 0; k <= p.size(); ++k)
        d << 1e3 * p[k % p.size()].x() << ' ' << 1e3 * p[k % p.size()].y() << '\n';
      d << '\n';
    }
    g << (first ? "" : ", ") << "'" << data.back().string() << "' w filledcurves closed fc rgb '"
      << region_colour(id) << "' fs solid 1.0 border lc rgb '#333333' lw 0.4 t \""
      << gnuplot_title(region_name(spec, id)) << "\"";
    first = false;
  }
  g << "\n";
  g.close();
  return run_gnuplot(script, data, why);
}

PolygonsByRegion mesh_polygons(const Mesh2D& mesh) {
  PolygonsByRegion out;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
    if (mesh.triangle_part[t] != region_shell) { // not physical coordinates
      const auto& tri = mesh.triangles[t];
      out[mesh.triangle_part[t]].push_back(
          {mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]});
    }
  return out;
}

PlaneFrame coordinate_plane(char axis) {
  const Eigen::Vector3d n = Eigen::Vector3d::Unit(axis - 'x');
  // u, v chosen so that the picture reads as the usual view: y-cut shows x right, z up.
  const Eigen::Vector3d u = axis == 'x' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d v = axis == 'z' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  return {Eigen::Vector3d::Zero(), u, v, n};
}

PolygonsByRegion cut_polygons(const Mesh3D& mesh, const PlaneFrame& plane) {
  PolygonsByRegion out;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (mesh.tet_part[t] == region_shell_3d)
      continue;
    const auto& tet = mesh.tets[t];
    auto cut = cut_tet_by_plane(
        {mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]], mesh.nodes[tet[3]]}, plane);
    if (!cut.empty())
      out[mesh.tet_part[t]].push_back(std::move(cut));
  }
  return out;
}

VtuGrid mesh_grid(const std::vector<Eigen::Vector3d>& points, int cell_type,
                  const std::vector<std::vector<int>>& cells, const std::vector<int>& region) {
  VtuGrid g;
  g.points = points;
  VtuArray ids{"region_id", 1, {}, VtuType::Int32};
  for (std::size_t c = 0; c < cells.size(); ++c) {
    g.cell_types.push_back(cell_type);
    g.connectivity.insert(g.connectivity.end(), cells[c].begin(), cells[c].end());
    g.offsets.push_back(static_cast<int>(g.connectivity.size()));
    ids.values.push_back(region[c]);
  }
  g.cell_data.push_back(std::move(ids));
  return g;
}

struct MeshOutputs {
  nlohmann::ordered_json summary;
  VtuGrid grid;
  PolygonsByRegion picture;
  std::string xlabel, ylabel;
};

MeshOutputs mesh_2d(CaseSpec& spec, const MeshOptions& o) {
  const Mesh2D mesh = mesh_case_2d(spec, o.overrides);
  MeshOutputs out;
  const RegionTable table = region_table(mesh, spec.axisymmetric());
  auto& j = out.summary;
  j["elements"] = mesh.n_triangles();
  j["nodes"] = mesh.n_nodes();
  j["unknowns"] = DofMap2D(mesh, spec.order).n_dofs();
  j["regions"] = regions_json(spec, table, spec.axisymmetric());
  j["shell_elements"] =
      std::count(mesh.triangle_part.begin(), mesh.triangle_part.end(), region_shell);
  j["mesh_quality"] = {{"min_angle_deg", mesh.quality.min_angle_deg},
                       {"max_angle_deg", mesh.quality.max_angle_deg}};
  print_regions(spec, table, spec.axisymmetric() ? "volume_m3" : "area_m2");
  std::vector<Eigen::Vector3d> points;
  for (const auto& p : mesh.nodes)
    points.emplace_back(p.x(), p.y(), 0);
  std::vector<std::vector<int>> cells;
  std::vector<int> region;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
    if (mesh.triangle_part[t] != region_shell)
      cells.push_back({mesh.triangles[t][0], mesh.triangles[t][1], mesh.triangles[t][2]}),
          region.push_back(mesh.triangle_part[t]);
  out.grid = mesh_grid(points, 5, cells, region);
  out.picture = mesh_polygons(mesh);
  out.xlabel = spec.axisymmetric() ? "r" : "x";
  out.ylabel = spec.axisymmetric() ? "z" : "y";
  return out;
}

MeshOutputs mesh_3d(CaseSpec& spec, const MeshOptions& o) {
  MeshEstimate3D estimate;
  const Mesh3D mesh = mesh_case_3d(spec, o.overrides, estimate);
  MeshOutputs out;
  const RegionTable table = region_table(mesh);
  auto& j = out.summary;
  j["elements"] = mesh.n_tets();
  j["nodes"] = mesh.n_nodes();
  j["unknowns"] = DofMap3D(mesh, spec.order).n_dofs();
  j["regions"] = regions_json(spec, table, true);
  j["shell_elements"] = std::count(mesh.tet_part.begin(), mesh.tet_part.end(), region_shell_3d);
  j["mesh_quality"] = {{"min_dihedral_deg", mesh.quality.min_dihedral_deg},
                       {"max_dihedral_deg", mesh.quality.max_dihedral_deg},
                       {"max_radius_edge", mesh.quality.max_radius_edge}};
  // TetGen met the domain as two pieces cut at this sphere (0: one piece), mesh/domain_split3d.hpp.
  j["mesh_split_radius_mm"] = mesh.split_radius * 1e3;
  j["warnings"] = mesh.warnings;
  print_regions(spec, table, "volume_m3");
  if (mesh.split_radius > 0)
    std::printf("meshed as two pieces at once, cut at the sphere r = %.6g mm\n",
                mesh.split_radius * 1e3);
  for (const auto& w : mesh.warnings)
    std::cerr << "magfem: warning: " << w << "\n";
  std::vector<std::vector<int>> cells;
  std::vector<int> region;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (mesh.tet_part[t] != region_shell_3d)
      cells.push_back({mesh.tets[t][0], mesh.tets[t][1], mesh.tets[t][2], mesh.tets[t][3]}),
          region.push_back(mesh.tet_part[t]);
  out.grid = mesh_grid(mesh.nodes, 10, cells, region);
  const PlaneFrame plane = coordinate_plane(o.plane);
  out.picture = cut_polygons(mesh, plane);
  out.xlabel = std::string(1, static_cast<char>('x' + (o.plane == 'x')));
  out.ylabel = o.plane == 'z' ? "y" : "z";
  j["picture_plane"] = std::string(1, o.plane) + " = 0";
  return out;
}

} // namespace

std::vector<OptionInfo> mesh_option_infos() {
  return mesh_option_table().options();
}

int run_mesh_command(const std::vector<std::string>& args) {
  const auto t0 = std::chrono::steady_clock::now();
  MeshOptions o;
  const auto positional = mesh_option_table().parse(args, o);
  if (positional.size() != 1)
    throw InputError("<command line>", 0, "", "mesh takes one case file");
  const std::string case_file = positional[0];
  if (o.out_dir.empty())
    o.out_dir = (std::filesystem::path("out") /
                 (std::filesystem::path(case_file).stem().string() + "_mesh"))
                    .string();
  CaseSpec spec = read_case(case_file, o.parameters);
  MeshOutputs out = spec.dimension == 3 ? mesh_3d(spec, o) : mesh_2d(spec, o);
  nlohmann::ordered_json j;
  j["case"] = case_file;
  j["dimension"] = spec.dimension == 3 ? "3d" : spec.axisymmetric() ? "axisymmetric" : "planar";
  j["order"] = spec.order;
  j.update(out.summary);
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  add_provenance(j);

  OutputStage stage(o.out_dir);
  std::vector<std::string> region_names;
  for (const auto& r : spec.regions)
    region_names.push_back(r.name);
  add_cell_names(out.grid, "region_id", "region", "region_names", region_names);
  write_vtu(stage.path_for("mesh.vtu").string(), std::move(out.grid));
  std::string why;
  if (!plot_polygons(out.picture, spec,
                     case_file + " (" + std::to_string(j["elements"].get<long>()) + " elements)",
                     out.xlabel, out.ylabel, stage.path_for("mesh.png"), why))
    std::cerr << "magfem: note: no mesh.png: " << why << "\n";
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();
  std::printf("%s elements, %s nodes, %s DOFs at order %d (%.2f s)\n", j["elements"].dump().c_str(),
              j["nodes"].dump().c_str(), j["unknowns"].dump().c_str(), spec.order,
              j["seconds"].get<double>());
  std::cout << "wrote    " << o.out_dir << "/";
  const auto files = stage.written();
  for (std::size_t i = 0; i < files.size(); ++i)
    std::cout << (i ? ", " : "") << files[i];
  std::cout << "\n";
  return 0;
}

} // namespace magfem
