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

// An accuracy and limits given beside the case (`solve --accuracy --max-passes --max-unknowns`,
// Python's Case.solve(accuracy=, max_passes=, max_unknowns=)); unset ones keep the case's.
struct AdaptOverrides {
  std::optional<double> accuracy_pct, max_unknowns;
  std::optional<int> max_passes;
};

// The caller's names of the three settings, for messages.
struct AdaptOverrideNames {
  std::string file, accuracy, max_passes, max_unknowns;
};

// Applies `o` over the case's adapt: section. A limit with no accuracy from either is an
// InputError naming the limit: limits of a solve that does not adapt would be silently
// ignored.
void apply_adapt_overrides(AdaptSpec& a, const AdaptOverrides& o, const AdaptOverrideNames& n);

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
