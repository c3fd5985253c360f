#include "app/command_help.hpp"

#include <array>

namespace magfem {

namespace {

struct CommandHelp {
  const char* name;
  const char* synopsis; // one line per form
  const char* summary;  // the overview's one-liner
  const char* details;  // options and outputs
};

constexpr std::array<CommandHelp, 7> commands{{
    {"solve", "magfem solve CASE.yaml [--out DIR] [--order 1|2] [--mesh-scale S] [--quiet]",
     "mesh and solve a case by FE",
     "  Writes into DIR (default out/<case name>): summary.json (energy, forces, coils,\n"
     "  mesh and solver figures, magfem_version and commit), one CSV per probe, forces.csv\n"
     "  and solution.vtu for ParaView.\n"
     "  --order 1|2       element order (overrides the case's mesh.order)\n"
     "  --mesh-scale S    multiply every mesh size by S (S > 1 is coarser)\n"
     "  --quiet           3D: no progress lines (stage, CG iteration every 2 s) on stderr\n"},
    {"analytic",
     "magfem analytic CASE.yaml [--out DIR] [--model charge|harmonic] [--tolerance T] "
     "[--n-max N]",
     "the same probes from the analytic models",
     "  3D magnets in air or with permeable spheres (spherical imaging) and coils\n"
     "  (Biot-Savart): the charge model, or the spherical-harmonic model.\n"
     "  --model charge|harmonic   (default charge)\n"
     "  --tolerance T             relative cubature tolerance of the charge model\n"
     "  --n-max N                 harmonic degree of the harmonic model\n"},
    {"compare", "magfem compare REFERENCE.csv TEST.csv", "compare two probe CSVs",
     "  Per field component: the rms discrepancy of thesis eq. 3.117 and the pointwise rms\n"
     "  error, in % of the reference.\n"},
    {"sweep",
     "magfem sweep CASE.yaml --rotate GROUP --axis x|y|z|ax,ay,az\n"
     "                    --angles START:STEP:END|A,B,C [--point px,py,pz] [--analytic]\n"
     "                    [--surface-radius R] [--jobs N] [--out DIR]\n"
     "       magfem sweep CASE.yaml --move GROUP --axis z --positions START:STEP:END|A,B,C\n"
     "                    [--jobs N] [--out DIR]          (axisymmetric cases)",
     "torque and force while a group of parts rotates (or, axisymmetric, moves)",
     "  Rotates GROUP (magnets, iron and coils) about the axis through the origin or --point\n"
     "  (right-hand rule) and writes sweep.csv (angle_deg,Tx,Ty,Tz,Fx,Fy,Fz: torque about\n"
     "  the origin and force on the group), sweep.png and summary.json. FE by default\n"
     "  (stress tensor on a sphere of radius R in the air gap, default mid-gap) or\n"
     "  --analytic: harmonic-form interaction when every magnet is a full-turn spherical\n"
     "  segment centred on the origin, magnetized along its own axis or radially, and a\n"
     "  sphere separates the group from the rest (milliseconds, truncation bound printed);\n"
     "  otherwise the charge interaction. summary.json `method` says which. Lengths in the\n"
     "  case's unit, angles in degrees.\n"
     "  Axisymmetric cases: --move translates GROUP along the axis by the positions (mm)\n"
     "  and writes sweep.csv (position_mm,Fz_N: the Lorentz force on the group).\n"
     "  --jobs N   positions solved in parallel (default: one per core)\n"},
    {"study",
     "magfem study CASE.yaml --param NAME=START:STEP:END|A,B,C [--param ...]\n"
     "                    --objective peak_torque|torque_at:DEG [--objective ...]\n"
     "                    --rotate GROUP --axis x|y|z|ax,ay,az [--angles LIST]\n"
     "                    [--analytic|--fe] [--jobs N] [--out DIR]",
     "evaluate torque objectives over a grid of case-file parameters",
     "  Every combination of the --param values (the file's `parameters:`, in each one's\n"
     "  own unit) is read and swept as `magfem sweep` does (analytic by default: the\n"
     "  harmonic form where it applies); the objectives take the torque about the axis on\n"
     "  GROUP: peak_torque is max |T| over --angles, torque_at:DEG the value at DEG. Writes\n"
     "  study.csv (one column per parameter, one per objective), study.png, summary.json\n"
     "  into DIR (default out/<case>_study). Exit 3 if a design failed (listed in\n"
     "  summary.json; the others are written).\n"},
    {"optimize",
     "magfem optimize CASE.yaml --vary NAME=LO:HI [--vary ...]\n"
     "                    --maximize|--minimize peak_torque|torque_at:DEG\n"
     "                    --rotate GROUP --axis x|y|z|ax,ay,az [--angles LIST]\n"
     "                    [--xtol T] [--verify-fe] [--out DIR]",
     "bounded optimization of a torque objective over case-file parameters",
     "  NLopt's COBYLA (derivative-free, bounded) on the analytic sweep of `magfem study`;\n"
     "  --xtol is its relative tolerance on the variables (default 1e-4). --verify-fe solves\n"
     "  the optimum by FE and reports the FE value beside the analytic one. Writes\n"
     "  summary.json into DIR (default out/<case>_optimize).\n"},
    {"validate",
     "magfem validate [--tier quick|full] [--only ID,...|--source SEED] [--jobs N] [--out DIR]",
     "recompute the published figures and report the agreement",
     "  Runs the catalogue (share/magfem/validation/catalogue.yaml when installed) and\n"
     "  writes results.csv, results.json, report.md and report.html into DIR (default\n"
     "  out/validate). Exit 0 when nothing fails, 4 when an entry fails, 2 on bad input.\n"},
}};

} // namespace

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const auto& c : commands)
    names.emplace_back(c.name);
  return names;
}

std::string usage_overview() {
  std::string text = "usage: magfem COMMAND [ARGS]\n       magfem --version\n"
                     "       magfem help COMMAND\n\ncommands:\n";
  for (const auto& c : commands) {
    std::string name = c.name;
    name.resize(10, ' ');
    text += "  " + name + c.summary + "\n";
  }
  text += "\nExit codes: 0 success, 1 internal error, 2 bad input (file, line and field named),\n"
          "3 the solver did not converge, 4 a validation entry failed.\n";
  return text;
}

std::optional<std::string> command_usage(const std::string& command) {
  for (const auto& c : commands)
    if (command == c.name)
      return std::string("usage: ") + c.synopsis + "\n\n  " + c.summary + ".\n" + c.details;
  return std::nullopt;
}

} // namespace magfem
