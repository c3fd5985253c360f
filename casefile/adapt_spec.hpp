#pragma once
// What an adaptive solve aims at (`adapt:` in a case file, or `solve --accuracy`): refine the
// mesh pass by pass until the estimated energy error and the change of the named quantities
// are below accuracy_pct. 2D planar, axisymmetric and 3D cases.
#include <optional>
#include <string>
#include <vector>

namespace magfem {

struct CaseSpec;

struct AdaptSpec {
  double accuracy_pct = 0;             // 0 = no adaptive refinement
  std::vector<std::string> quantities; // "energy", "forces.NAME.COMPONENT", "probes.NAME"
  int max_passes = 10;
  double max_unknowns = 4.0e6;
  int line = 0; // of `adapt:` in the case file (0: from the command line)

  bool enabled() const { return accuracy_pct > 0; }
};

// A named quantity resolved against the case. Force components: Fx Fy Fz Tx Ty Tz, or
// force / torque for the magnitude. A probe stands for the rms |B| over its samples.
struct AdaptQuantity {
  enum class Kind { energy, force, probe };
  Kind kind = Kind::energy;
  std::string name;      // the force or probe name
  std::string component; // forces only
};

// The quantity called `text`, or nullopt with the reason in `why` (unknown force or probe,
// unknown component, bad syntax).
std::optional<AdaptQuantity> parse_adapt_quantity(const std::string& text, const CaseSpec& c,
                                                  std::string& why);

} // namespace magfem
