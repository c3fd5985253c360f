#pragma once
// The validation catalogue (validation/catalogue.yaml): one entry per published figure, with
// where it was published, the value, the tolerance and its reason, and how magfem computes
// it (a named evaluator with its parameters). The catalogue is data; the evaluators are the
// small registry in validate_evaluators.hpp.
#include <optional>
#include <string>
#include <vector>

#include "core/yaml_node.hpp"

namespace magfem {

enum class ValidationTier { quick, full };

// An FE value solved to an accuracy (evaluate.fe with accuracy_pct): the adaptive loop
// (pipeline/adapt_loop.hpp) refines from a coarse first mesh until the estimated error of
// `quantity` (and the energy's) is below the tier's accuracy. Entries without one keep fixed
// mesh scales (evaluate.fe.quick / full) and say why in evaluate.fe.reason.
struct FeAccuracy {
  double quick_pct = 0, full_pct = 0; // per tier; 0: no FE in that tier
  std::string quantity;               // energy, probes.NAME or forces.NAME.COMPONENT
  double start_scale = 1;             // mesh scale of the first pass
  int max_passes = 10;
  double max_unknowns = 4.0e6;
  double pct(ValidationTier tier) const {
    return tier == ValidationTier::quick ? quick_pct : full_pct;
  }
};

struct CatalogueEntry {
  std::string id;
  std::string source;  // seed file, e.g. 003_8d5b5c90a0e7438f.txt
  std::string section; // section / table / figure
  std::string quantity;
  std::string unit;
  std::optional<double> published; // absent for entries not yet computed (skipped)
  double tolerance_pct = 0;
  std::string tolerance_reason;
  // relative: |value - published| / |published| <= tolerance_pct;
  // at_most:  the value is itself a percentage (an error measure) and must be <= tolerance_pct.
  enum class Check { relative, at_most } check = Check::relative;
  // compute: pass/fail; finding: published value we show cannot be reproduced as printed
  // (the evaluator still runs: it is the independent computation); skipped: not evaluated.
  enum class Expect { compute, finding, skipped } expect = Expect::compute;
  std::string reason;                          // finding / skipped: why
  std::string paper;                           // what the paper says (report paragraph)
  ValidationTier tier = ValidationTier::quick; // lowest tier that runs the entry
  std::string evaluator;
  std::string evaluator_quantity;        // evaluate.quantity
  std::string case_file;                 // resolved path, empty if none
  std::optional<YamlNode> evaluate;      // the whole evaluate map (evaluator parameters)
  std::optional<FeAccuracy> fe_accuracy; // evaluate.fe asks for an accuracy (else mesh scales)
  std::string fe_reason;                 // evaluate.fe.reason: why the accuracy, or the scales
  int line = 0;
};

// The citation of a source document (catalogue `sources:`), printed by the report.
struct SourceCitation {
  std::string file; // seed file, as CatalogueEntry::source names it
  std::string cite; // short form for tables, e.g. "Harwin 2018"
  std::string authors, title, venue, year;
  std::string link; // DOI or URL, may be empty
  std::string note; // what the source text does not print, may be empty
};

struct Catalogue {
  std::string file;
  std::vector<SourceCitation> sources; // in the catalogue's order
  std::vector<CatalogueEntry> entries;
};

// Reads and checks the catalogue: every field, unique ids, the evaluator and its quantity
// known to the registry, case files present, an FE accuracy in (0, 100) % with a quantity the
// case has and an evaluator that can adapt, (paths relative to the catalogue's folder), and
// when the catalogue lists `sources`, every entry's source among them.
// Throws InputError naming the entry id, file and line.
Catalogue read_catalogue(const std::string& path);

std::string to_string(ValidationTier tier);
std::string to_string(CatalogueEntry::Check check);
std::string to_string(CatalogueEntry::Expect expect);

} // namespace magfem
