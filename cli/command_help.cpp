#include "cli/command_help.hpp"

#include <array>

namespace magfem {

namespace {

struct CommandHelp {
  const char* name;
  const char* synopsis; // one line per form
  const char* summary;  // the overview's one-liner
  const char* details;  // options and outputs
};

constexpr std::array<CommandHelp, 10> commands{{
    {"solve",
     "magfem solve CASE.yaml [--out DIR] [--order 1|2] [--mesh-scale S] [--max-memory GB]\n"
     "                    [--accuracy PCT [--max-passes N] [--max-unknowns N]]\n"
     "                    [--param NAME=VALUE ...] [--quiet]",
     "mesh and solve a case by FE",
     "  Writes into DIR (default out/<case name>): summary.json (energy, forces, coils,\n"
     "  mesh and solver figures, magfem_version and commit), one CSV per probe, forces.csv,\n"
     "  sections.csv (3D: flux through the case's sections) and solution.vtu for ParaView.\n"
     "  --order 1|2       element order (overrides the case's mesh.order)\n"
     "  --mesh-scale S    multiply every mesh size by S (S > 1 is coarser)\n"
     "  --max-memory GB   refuse (exit 2) a mesh whose estimated peak memory exceeds GB\n"
     "                    (default: the memory available now) and say which --mesh-scale\n"
     "                    would fit; 3D: estimated before meshing, 2D: from the mesh\n"
     "  --accuracy PCT    refine adaptively until the estimated energy error and the\n"
     "                    change of the case's adapt.quantities are below PCT percent\n"
     "                    (overrides the case's adapt:; summary.json gains adapt.passes;\n"
     "                    3D: each pass a new TetGen mesh sized from the error estimate)\n"
     "  --max-passes N    adaptive passes at most (default 10); then converged: false\n"
     "  --max-unknowns N  stop before a pass that would need more DOFs (default 4e6)\n"
     "  --quiet           3D: no progress lines (stage, CG iteration every 2 s) on stderr\n"
     "  --param NAME=VALUE  set one of the case file's `parameters:` (repeatable)\n"
     "  3D cases (coils, nonlinear iron too) also run distributed: mpirun -n N magfem solve\n"
     "  CASE.yaml --out DIR (each process meshes, assembles 1/N of the elements; rank 0\n"
     "  writes; docs/performance.md).\n"},
    {"analytic",
     "magfem analytic CASE.yaml [--out DIR] [--model charge|harmonic] [--tolerance T] "
     "[--n-max N]\n"
     "                    [--param NAME=VALUE ...]",
     "the same probes from the analytic models",
     "  3D magnets in air or with permeable spheres (spherical imaging) and coils\n"
     "  (Biot-Savart): the charge model, or the spherical-harmonic model; with coils also\n"
     "  forces.csv and the coils' force, torque, linkage and inductance (summary.json).\n"
     "  Axisymmetric cases: coils and axial magnets exactly (loops, current sheets), F_z.\n"
     "  Iron is refused (exit 2, naming the region).\n"
     "  --model charge|harmonic   (default charge)\n"
     "  --tolerance T             relative cubature tolerance of the charge model\n"
     "  --n-max N                 harmonic degree of the harmonic model\n"
     "  --param NAME=VALUE        set one of the case file's `parameters:` (repeatable)\n"},
    {"mesh",
     "magfem mesh CASE.yaml [--out DIR] [--order 1|2] [--mesh-scale S] [--plane x|y|z]\n"
     "                    [--param NAME=VALUE ...]",
     "the mesh a solve would use, to look at before solving",
     "  Meshes the case exactly as `magfem solve` would (same sizes, --mesh-scale, memory\n"
     "  guard) and stops. Prints per region its elements, area (planar) or volume and the\n"
     "  shortest and longest element edge; writes into DIR (default out/<case>_mesh):\n"
     "  summary.json (elements, nodes, DOFs at the order as `unknowns`, regions, mesh\n"
     "  quality, the mesher's warnings), mesh.vtu (region_id and region name per cell) and\n"
     "  mesh.png (2D: the mesh coloured by region; 3D: its cut by the plane through the\n"
     "  origin normal to --plane, default y, i.e. the xz plane). The open boundary's shell is\n"
     "  left out.\n"
     "  --order 1|2       the order whose DOFs are counted\n"
     "  --mesh-scale S    multiply every mesh size by S, as in solve\n"
     "  --plane x|y|z     3D: the cut mesh.png shows\n"
     "  --param NAME=VALUE  set one of the case file's `parameters:` (repeatable)\n"},
    {"compare", "magfem compare REFERENCE.csv TEST.csv", "compare two probe CSVs",
     "  Per field component: the rms discrepancy of thesis eq. 3.117 and the pointwise rms\n"
     "  error, in % of the reference (n/a where the reference component is zero), and the\n"
     "  largest and rms differences in T.\n"},
    {"sweep",
     "magfem sweep CASE.yaml --rotate GROUP --axis x|y|z|ax,ay,az\n"
     "                    --angles START:STEP:END|A,B,C [--point px,py,pz] [--analytic]\n"
     "                    [--surface-radius R] [--order 1|2] [--mesh-scale S] [--jobs N]\n"
     "                    [--max-memory GB] [--resume] [--quiet] [--out DIR]\n"
     "       magfem sweep CASE.yaml --move GROUP --axis x|y|z|ax,ay,az\n"
     "                    --positions START:STEP:END|A,B,C [--analytic] [--order 1|2]\n"
     "                    [--point px,py,pz] [--mesh-scale S] [--max-memory GB]\n"
     "                    [--jobs N] [--resume] [--quiet] [--out DIR]\n"
     "                    (3D, planar and axisymmetric cases; planar: --axis x|y|dx,dy,\n"
     "                    FE only; axisymmetric: --axis z, FE only)",
     "torque and force while a group of parts rotates or moves along a line",
     "  Rotates GROUP (magnets, iron and coils) about the axis through the origin or --point\n"
     "  (right-hand rule) and writes sweep.csv (angle_deg,Tx,Ty,Tz,Fx,Fy,Fz: torque about\n"
     "  the origin and force on the group), sweep.png and summary.json. FE by default\n"
     "  (stress tensor on a sphere of radius R in the air gap, default mid-gap) or\n"
     "  --analytic: harmonic-form interaction when every magnet is a full-turn spherical\n"
     "  segment centred on the origin, magnetized along its own axis or radially, and a\n"
     "  sphere separates the group from the rest (milliseconds, truncation bound printed);\n"
     "  magnets of any shape outside such bodies: their exterior harmonic field at the\n"
     "  magnets' charges; otherwise face-pair cubature of the charge interaction (both with\n"
     "  an estimated error printed). summary.json `method` says which. Lengths in the\n"
     "  case's unit, angles in degrees.\n"
     "  Planar 2D cases: --rotate GROUP --axis z turns the regions with `group: GROUP`\n"
     "  about --point (default the origin; px,py,0) and takes the torque about it (Tz)\n"
     "  and the force on the group from the Lorentz force on its coils, else the case's\n"
     "  one `band` (or `circle`) force around it: cogging torque against rotor angle.\n"
     "  Planar 2D cases: --move GROUP --axis x|y|dx,dy translates those regions in the\n"
     "  plane by the positions (mm), their magnetizations and the `circle` or `band`\n"
     "  force around them with them, and writes sweep.csv with position_mm in place of\n"
     "  angle_deg: force per metre against gap, Tz about --point moved with the group.\n"
     "  3D cases: --move translates GROUP along --axis by the positions (mm) and writes\n"
     "  sweep.csv with position_mm in place of angle_deg (force against gap); the stress\n"
     "  sphere about the origin is chosen mid-gap at each position (--analytic as above);\n"
     "  the torque is about the origin, or about --point moved with the group.\n"
     "  Axisymmetric cases: --move translates GROUP along the axis by the positions (mm)\n"
     "  and writes sweep.csv (position_mm,Fz_N: the force on the group: the Lorentz\n"
     "  force on its coils, else the reaction of the others' coils, else the case's\n"
     "  `contour` force on one of its regions, e.g. a magnet over steel).\n"
     "  --jobs N   positions solved in parallel (default: one per core); FE positions\n"
     "             share the memory limit (--max-memory, else the memory available): fewer\n"
     "             run at once if N do not fit (said on stderr, summary.json `jobs`)\n"
     "  --resume   continue a sweep that was interrupted (Ctrl-C, kill, crash): every\n"
     "             finished position is kept in DIR/.magfem-checkpoint.jsonl as it\n"
     "             finishes, and is not solved again; the outputs are those of an\n"
     "             uninterrupted run. Refused if the case file or options changed.\n"
     "  Under mpirun (mpirun -n N magfem sweep ...) the positions are dealt to the N\n"
     "  processes one at a time as each finishes one; each position is a serial solve\n"
     "  of its process, which takes its share of its machine's cores (positions at\n"
     "  once unless --jobs, element-loop threads unless MAGFEM_THREADS). Rank 0 keeps\n"
     "  the checkpoint (--resume works with or without mpirun) and writes the outputs\n"
     "  of a serial run, byte for byte but for the times (summary.json `seconds`,\n"
     "  `peak_memory_MB`). A bad option or case ends every process with exit 2.\n"},
    {"study",
     "magfem study CASE.yaml --param NAME=START:STEP:END|A,B,C [--param ...]\n"
     "                    --objective peak_torque|torque_at:DEG [--objective ...]\n"
     "                    --rotate GROUP --axis x|y|z|ax,ay,az [--angles LIST]\n"
     "                    [--analytic|--fe] [--mesh-scale S] [--order 1|2] [--jobs N]\n"
     "                    [--accuracy PCT [--max-passes N] [--max-unknowns N]]\n"
     "                    [--quiet] [--resume] [--out DIR]",
     "evaluate torque objectives over a grid of case-file parameters",
     "  Every combination of the --param values (the file's `parameters:`, in each one's\n"
     "  own unit) is read and swept as `magfem sweep` does (analytic by default: the\n"
     "  harmonic form where it applies); the objectives take the torque about the axis on\n"
     "  GROUP: peak_torque is max |T| over --angles, torque_at:DEG the value at DEG. Writes\n"
     "  study.csv (one column per parameter, one per objective), study.png (a contour map\n"
     "  for two parameters, else lines), summary.json into DIR (default out/<case>_study).\n"
     "  --mesh-scale and --order set the --fe sweep's mesh as in `solve`. Exit 3 if a\n"
     "  design failed (listed in summary.json; the others are written).\n"
     "  --fe: study.csv also has <objective>_err (N m) for each objective, its estimated\n"
     "  error. With --accuracy (or the case's adapt:) every position a design needs is\n"
     "  refined adaptively for its torque, as `solve --accuracy` does; summary.json's\n"
     "  `adapt` lists each design's passes, unknowns and whether it converged, and a\n"
     "  design that stopped at --max-passes/--max-unknowns first is a warning.\n"
     "  --resume   continue a study that was interrupted (Ctrl-C, kill, crash): every\n"
     "             finished design is kept in DIR/.magfem-checkpoint.jsonl as it\n"
     "             finishes, and is not evaluated again; the outputs are those of an\n"
     "             uninterrupted run. Refused if the case file or options changed.\n"
     "  Under mpirun (mpirun -n N magfem study ...) the designs are dealt to the N\n"
     "  processes one at a time as each finishes one; a design's sweep runs on its\n"
     "  process's share of the machine's cores (its positions --jobs at once). Rank 0\n"
     "  keeps the checkpoint (--resume works with or without mpirun) and writes the\n"
     "  outputs of a serial --jobs 1 run (summary.json but `seconds`); every process\n"
     "  exits with the same code.\n"},
    {"optimize",
     "magfem optimize CASE.yaml --vary NAME=LO:HI [--vary ...]\n"
     "                    --maximize|--minimize peak_torque|torque_at:DEG\n"
     "                    --rotate GROUP --axis x|y|z|ax,ay,az [--angles LIST]\n"
     "                    [--constraint \"EXPR <= EXPR\" ...] [--xtol T] [--verify-fe]\n"
     "                    [--mesh-scale S] [--order 1|2] [--accuracy PCT [--max-passes N]\n"
     "                    [--max-unknowns N]] [--quiet] [--out DIR]",
     "bounded optimization of a torque objective over case-file parameters",
     "  NLopt's COBYLA (derivative-free, bounded) on the analytic sweep of `magfem study`;\n"
     "  --xtol is its relative tolerance on the variables (default 1e-4). --constraint is an\n"
     "  inequality (<= or >=) between expressions of the --vary names in their own units,\n"
     "  e.g. \"R_out - R_in >= 10\"; exit 3 if no point satisfies it. --verify-fe solves\n"
     "  the optimum by FE (mesh as set by --mesh-scale/--order) and reports the FE value\n"
     "  beside the analytic one, with its estimated error; --accuracy (or the case's\n"
     "  adapt:) refines that FE check adaptively (summary.json fe_adapt). Writes\n"
     "  summary.json and history.csv (every evaluation: the variables and the\n"
     "  objective) into DIR (default out/<case>_optimize).\n"
     "  Refused under mpirun: each step is chosen from the ones before, so there is\n"
     "  nothing to deal; `mpirun -n N magfem study` spreads a grid of designs instead.\n"},
    {"actuator",
     "magfem actuator CASE.yaml --rotor GROUP --orientations SPEC [--torque Tx,Ty,Tz]\n"
     "                    [--analytic] [--param NAME=VALUE ...] [--order 1|2]\n"
     "                    [--mesh-scale S] [--coil-quadrature R,A,P,Z] [--verify] [--quiet]\n"
     "                    [--accuracy PCT [--max-passes N] [--max-unknowns N]]\n"
     "                    [--coil-pitch START:STEP:END] [--out DIR]",
     "torque constants, commutated currents and copper loss of a multi-coil actuator",
     "  For every rotor orientation: the torque constants Gamma (3 x coils, N m/A: the\n"
     "  Lorentz torque about the origin of each coil at 1 A in the field of the magnets\n"
     "  and iron), the currents of least copper loss i = R^-1 Gamma^T (Gamma R^-1 Gamma^T)^-1\n"
     "  T_d (thesis eq. 5.4 weighted by the coil resistances R; the least two-norm for equal\n"
     "  coils), the copper loss sum R_k i_k^2, the peak current and cond(Gamma).\n"
     "  SPEC: rx=A,ry=B,rz=C, each START:STEP:END, a number or a list (degrees; a missing\n"
     "  axis is 0), or a CSV with the header rx_deg,ry_deg,rz_deg. The rotor turns by rx\n"
     "  about the fixed x axis, then ry about y, then rz about z: R = Rz Ry Rx.\n"
     "  --analytic: the charge model with spherical imaging (iron as full permeable\n"
     "  spheres); otherwise FE of the magnets and iron, one solve when the field turns\n"
     "  rigidly with the rotor, else one per orientation. Without --torque the three unit\n"
     "  torques (1 N m about x, y, z) give P_x, P_y, P_z. Writes commutation.csv (or\n"
     "  commutation_x/y/z.csv), torque_constants.csv, power_map.png and summary.json into\n"
     "  DIR (default out). Ill-conditioned orientations keep cond_Gamma, no currents.\n"
     "  Gamma and T_d are the torque on the coils (thesis eq. 5.2); the rotor gets -T_d.\n"
     "  --coil-quadrature R,A,P,Z: per coil R Gauss radii, P panels of A Gauss points\n"
     "  across the bundle, Z azimuths (default 4,3,2,32: ~1e-3 of the largest constant).\n"
     "  --verify: FE with the commutated currents at the first, middle and last\n"
     "  orientation; summary.json `verification` lists demanded and produced torque.\n"
     "  --accuracy PCT (with --verify; or the case's adapt:) refines each of these solves\n"
     "  adaptively for the torque it reports, as `solve --accuracy` does, and puts its\n"
     "  estimated error beside it (produced_error_estimate_Nm, `adapt`); one that stops\n"
     "  at --max-passes/--max-unknowns first is a warning. The torque constants keep\n"
     "  the case's mesh.\n"
     "  Under mpirun (mpirun -n N magfem actuator ... --verify) these FE solves are\n"
     "  dealt to the processes (each computes the constants; rank 0 writes); without\n"
     "  --verify the command is refused under mpirun.\n"
     "  FE runs show the orientation, stage and solver residual on stderr, --analytic\n"
     "  the charge model's share of points done; --quiet turns that off.\n"
     "  --coil-pitch START:STEP:END (deg): the thesis's coil-pitch study (sec. 5.3) instead\n"
     "  of the case's coils: coil_pitch.csv (mean copper loss against pitch), coil_pitch.png.\n"},
    {"materials", "magfem materials [NAME | --export NAME]",
     "list the bundled materials, show one, or write one's B-H table as CSV",
     "  Without options: one line per bundled entry (name, kind, other names; magnets their\n"
     "  B_r and the knee data the demagnetization check uses, H_cJ and its temperature\n"
     "  coefficient).\n"
     "  NAME            the entry in full: B_r, mu_r, H_cJ with their temperature\n"
     "                  coefficients and the knee B_r(T) - mu0 mu_r H_cJ(T) from 20 to\n"
     "                  150 C (magnets), the B-H table's extent (soft), and the source.\n"
     "  --export NAME   writes the B-H table of the soft entry NAME to stdout in the format\n"
     "                  a case's `bh_file:` reads (a '#' line with its source, the header\n"
     "                  H_Apm,B_T, then H in A/m and B in T), e.g.\n"
     "                  magfem materials --export steel_1010 > my_steel.csv\n"},
    {"validate",
     "magfem validate [--tier quick|full] [--only ID,...|--source SEED] [--jobs N] [--resume]\n"
     "                [--catalogue FILE] [--out DIR]",
     "recompute the published figures and report the agreement",
     "  Runs the catalogue (share/magfem/validation/catalogue.yaml when installed) and\n"
     "  writes results.csv, results.json, report.md and report.html into DIR (default\n"
     "  out/validate). Exit 0 when nothing fails, 4 when an entry fails, 2 on bad input.\n"
     "  --tier quick (default): every analytic figure and the 2D FE ones, a few minutes on\n"
     "  2 cores; --tier full: also the 3D FE figures on publication meshes (the 32-magnet\n"
     "  benchmark, the compensator), about 25 min on 2 cores and up to ~7 GB per job.\n"
     "  FE entries that name an accuracy are solved adaptively to it (results.csv: passes,\n"
     "  unknowns, converged); one that stops at a limit before it fails, saying why.\n"
     "  Finished entries are kept in DIR/.magfem-checkpoint.jsonl as they finish: after\n"
     "  Ctrl-C or kill, --resume evaluates only the rest (failed entries again) and writes\n"
     "  the same results as an uninterrupted run. --catalogue FILE runs another catalogue\n"
     "  (the same format; case paths relative to FILE).\n"
     "  Under mpirun (mpirun -n N magfem validate ...) the entries are dealt to the N\n"
     "  processes one at a time (each on --jobs threads, default its share of the\n"
     "  machine's cores); rank 0 keeps the checkpoint and writes the serial run's\n"
     "  outputs (but the times); every process exits with the same code.\n"},
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
