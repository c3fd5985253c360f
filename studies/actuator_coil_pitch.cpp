#include "studies/actuator_coil_pitch.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include <unistd.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "pipeline/build_info.hpp"
#include "studies/actuator_plot.hpp"
#include "studies/sweep.hpp"

namespace magfem {
namespace {

const std::string cli = "<command line>";

// Azimuths (radians) of a row: its n positions nearest phi = 0 among offset + k pitch (k
// integer); a position whose mirror image is not taken goes to phi = pi (the back).
std::vector<double> row_azimuths(int n, double pitch, bool offset) {
  std::vector<double> candidates;
  for (int k = 0; static_cast<int>(candidates.size()) < n + 2; ++k) {
    const double a = (offset ? k + 0.5 : k) * pitch;
    candidates.push_back(a);
    if (a > 0)
      candidates.push_back(-a);
  }
  std::vector<double> out(candidates.begin(), candidates.begin() + n);
  // A lone position (the +a of a pair whose -a did not make it) moves to the back.
  if (n < static_cast<int>(candidates.size()) && std::abs(out.back()) > 0 &&
      std::abs(candidates[static_cast<std::size_t>(n)] + out.back()) < 1e-12)
    out.back() = pi;
  return out;
}

Coil3D placed(const Coil3D& tpl, const std::string& name, double theta, double phi, double gap,
              double width) {
  Coil3D c = tpl;
  c.name = name;
  c.current = 0;
  auto& s = std::get<SphericalCoil>(c.shape);
  s.alpha_min = gap;
  s.alpha_max = gap + width;
  const Eigen::Vector3d axis(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                             std::cos(theta));
  c.placement.rotation =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  c.placement.translation.setZero();
  return c;
}

// "c<k>" (std::string{"c"} + ... trips a GCC 12 -Wrestrict false positive when inlined).
std::string coil_name(int k) {
  std::string name = std::to_string(k);
  name.insert(name.begin(), 'c');
  return name;
}

} // namespace

std::vector<Coil3D> thesis_coil_array(const Coil3D& tpl, double pitch) {
  const double outer = 0.9 * std::sqrt(2.0) * pitch / 4; // eq. 5.7 less 10 %
  const double gap = 0.2 * outer, width = 0.8 * outer;   // eq. 5.5: G_w = C_w / 4
  const int per_row = std::min(7, static_cast<int>(std::floor(2 * pi / pitch + 1e-9)));
  std::vector<Coil3D> out;
  int k = 0;
  for (const double phi : row_azimuths(per_row, pitch, true))
    out.push_back(placed(tpl, coil_name(++k), pi / 2 - pitch / 4, phi, gap, width));
  for (const double phi : row_azimuths(per_row, pitch, false))
    out.push_back(placed(tpl, coil_name(++k), pi / 2 + pitch / 4, phi, gap, width));
  return out;
}

const CoilPitchRow& CoilPitchStudy::minimum() const {
  return *std::min_element(rows.begin(), rows.end(),
                           [](const auto& a, const auto& b) { return a.mean_W() < b.mean_W(); });
}

CoilPitchStudy run_coil_pitch_study(const CaseSpec& spec, const ActuatorOptions& options,
                                    const std::vector<double>& pitches_deg,
                                    const std::vector<Orientation>& orientations, double torque_Nm,
                                    double table_step_deg) {
  if (spec.geometry3d.coils.empty())
    throw InputError(spec.file, 0, "coils", "the coil-pitch study needs a template coil");
  const Coil3D& tpl = spec.geometry3d.coils.front();
  const auto* sc = std::get_if<SphericalCoil>(&tpl.shape);
  if (!sc || tpl.placement.translation.norm() > 1e-12)
    throw InputError(spec.file, spec.coil_lines.empty() ? 0 : spec.coil_lines.front(),
                     "coils." + tpl.name,
                     "the coil-pitch study takes its template from the first coil, which must "
                     "be a circular_coil_on_sphere about the origin");
  for (const double p : pitches_deg)
    if (!(p >= 10 && p <= 120))
      throw InputError(cli, 0, "--coil-pitch",
                       "coil pitch " + std::to_string(p) + " deg is outside 10..120 deg");
  CoilPitchStudy study;
  study.n_orientations = orientations.size();
  const auto t0 = std::chrono::steady_clock::now();
  const FieldAtPoints b = analytic_rotor_field(spec, options.rotor, study.notes);
  const std::vector<CoilField> probe{CoilField(thesis_coil_array(tpl, 50 * deg_to_rad).front())};
  const RadialFieldTable table(b, quadrature_radii(probe, options.coil_rule),
                               table_step_deg * deg_to_rad);
  const FieldAtPoints interpolated = [&table](const std::vector<Eigen::Vector3d>& x) {
    return table(x);
  };
  study.table_step_deg = table.step_rad() / deg_to_rad;
  study.table_points = table.size();
  const auto t1 = std::chrono::steady_clock::now();
  study.table_seconds = std::chrono::duration<double>(t1 - t0).count();

  std::vector<Eigen::Matrix3d> rotations;
  for (const auto& o : orientations)
    rotations.push_back(rotor_rotation(o));
  for (const double pitch : pitches_deg) {
    CoilPitchRow row;
    row.pitch_deg = pitch;
    std::vector<CoilField> coils;
    for (const auto& c : thesis_coil_array(tpl, pitch * deg_to_rad))
      coils.emplace_back(c);
    const auto& s = std::get<SphericalCoil>(coils.front().coil().shape);
    row.n_coils = static_cast<int>(coils.size());
    row.gap_deg = s.alpha_min / deg_to_rad;
    row.width_deg = (s.alpha_max - s.alpha_min) / deg_to_rad;
    Eigen::VectorXd res(static_cast<Eigen::Index>(coils.size()));
    for (std::size_t k = 0; k < coils.size(); ++k)
      res(static_cast<Eigen::Index>(k)) = coils[k].resistance();
    // Orientations in chunks on two threads (bounded memory for the quadrature points).
    constexpr std::size_t chunk = 32;
    const std::size_t n_chunks = (rotations.size() + chunk - 1) / chunk;
    std::vector<std::array<double, 3>> sum(n_chunks, {0, 0, 0});
    std::vector<std::array<int, 3>> ill(n_chunks, {0, 0, 0});
    auto work = [&](std::size_t first, std::size_t stride) {
      for (std::size_t c = first; c < n_chunks; c += stride) {
        const std::vector<Eigen::Matrix3d> part(
            rotations.begin() + static_cast<std::ptrdiff_t>(c * chunk),
            rotations.begin() +
                static_cast<std::ptrdiff_t>(std::min(rotations.size(), (c + 1) * chunk)));
        for (const auto& g :
             torque_constants_rotating(coils, part, interpolated, options.coil_rule))
          for (int d = 0; d < 3; ++d) {
            const Commutation cm = commutate(g, res, torque_Nm * Eigen::Vector3d::Unit(d));
            if (cm.ok)
              sum[c][static_cast<std::size_t>(d)] += cm.power_W;
            else
              ++ill[c][static_cast<std::size_t>(d)];
          }
      }
    };
    std::thread other(work, 1, 2);
    work(0, 2);
    other.join();
    for (int d = 0; d < 3; ++d) {
      double total = 0;
      for (std::size_t c = 0; c < n_chunks; ++c) {
        total += sum[c][static_cast<std::size_t>(d)];
        row.n_ill[d] += ill[c][static_cast<std::size_t>(d)];
      }
      const int n_ok = static_cast<int>(rotations.size()) - row.n_ill[d];
      row.P_W[d] = n_ok > 0 ? total / n_ok : std::nan("");
    }
    study.rows.push_back(row);
  }
  study.study_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return study;
}

std::string coil_pitch_csv(const CoilPitchStudy& study) {
  std::string s = "coil_pitch_deg,n_coils,G_w_deg,C_w_deg,P_x_W,P_y_W,P_z_W,P_mean_W,"
                  "n_ill_x,n_ill_y,n_ill_z\n";
  char buf[256];
  for (const auto& r : study.rows) {
    std::snprintf(buf, sizeof buf, "%.10g,%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%d,%d,%d\n",
                  r.pitch_deg, r.n_coils, r.gap_deg, r.width_deg, r.P_W[0], r.P_W[1], r.P_W[2],
                  r.mean_W(), r.n_ill[0], r.n_ill[1], r.n_ill[2]);
    s += buf;
  }
  return s;
}

std::vector<double> coil_pitch_degrees(const ActuatorOptions& options) {
  if (!options.analytic)
    throw InputError(cli, 0, "--coil-pitch",
                     "the coil-pitch study uses the charge model: add --analytic");
  if (options.torque_Nm)
    throw InputError(cli, 0, "--torque",
                     "the coil-pitch study demands 1 N m about x, y and z in turn (thesis "
                     "sec. 5.3.3); leave out --torque");
  if (options.verify)
    throw InputError(cli, 0, "--verify", "not available with --coil-pitch");
  return parse_angle_list(options.coil_pitch, "--coil-pitch");
}

nlohmann::ordered_json coil_pitch_summary(const ActuatorOptions& options,
                                          const CoilPitchStudy& study) {
  const CoilPitchRow& best = study.minimum();
  nlohmann::ordered_json j;
  j["command"] = "actuator --coil-pitch";
  j["case"] = options.case_file;
  j["magfem_version"] = magfem_version();
  j["git_commit"] = magfem_git_commit();
  j["method"] = "charge_model";
  j["rotor"] = options.rotor;
  j["parameters"] = options.parameters;
  j["n_orientations"] = study.n_orientations;
  j["torque_Nm"] = 1.0;
  j["table_step_deg"] = study.table_step_deg;
  j["table_points"] = study.table_points;
  j["table_seconds"] = study.table_seconds;
  j["study_seconds"] = study.study_seconds;
  j["minimum"] = {{"coil_pitch_deg", best.pitch_deg},
                  {"n_coils", best.n_coils},
                  {"P_mean_W", best.mean_W()},
                  {"P_x_W", best.P_W[0]},
                  {"P_y_W", best.P_W[1]},
                  {"P_z_W", best.P_W[2]}};
  j["notes"] = study.notes;
  return j;
}

int run_coil_pitch_command(const ActuatorOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> pitches = coil_pitch_degrees(options);
  const std::vector<Orientation> orientations = parse_orientations(options.orientations);
  const CaseSpec spec = read_case(options.case_file, options.parameters);
  check_actuator_case(spec, options.rotor);
  const CoilPitchStudy study = run_coil_pitch_study(spec, options, pitches, orientations);

  std::filesystem::create_directories(options.out_dir);
  OutputStage stage(options.out_dir);
  stage.write_text("coil_pitch.csv", coil_pitch_csv(study));
  const CoilPitchRow& best = study.minimum();
  nlohmann::ordered_json j = coil_pitch_summary(options, study);
  std::string why;
  const auto scratch = std::filesystem::temp_directory_path() /
                       ("magfem_coil_pitch_" + std::to_string(::getpid()) + ".png");
  const bool plotted = plot_coil_pitch(study, spec.file, scratch, why);
  if (plotted) {
    std::filesystem::copy_file(scratch, stage.path_for("coil_pitch.png"),
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::remove(scratch);
  } else {
    std::cerr << "magfem: note: no coil_pitch.png: " << why << "\n";
  }
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  stage.write_text("summary.json", j.dump(2) + "\n");
  stage.commit();
  std::printf("%zu pitches x %zu orientations, B_r table %.2f deg (%zu points, %.1f s), study "
              "%.1f s\n",
              pitches.size(), orientations.size(), study.table_step_deg, study.table_points,
              study.table_seconds, study.study_seconds);
  std::printf("least mean loss %.4g W at coil pitch %g deg (%d coils; P_x %.4g, P_y %.4g, P_z "
              "%.4g W at 1 N m)\n",
              best.mean_W(), best.pitch_deg, best.n_coils, best.P_W[0], best.P_W[1], best.P_W[2]);
  std::printf("wrote    %s/coil_pitch.csv, summary.json%s\n", options.out_dir.c_str(),
              plotted ? ", coil_pitch.png" : "");
  return 0;
}

} // namespace magfem
