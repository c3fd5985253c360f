#include "validation/validate_catalogue.hpp"

#include <filesystem>
#include <set>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"
#include "validation/validate_evaluators.hpp"

namespace magfem {

std::string to_string(ValidationTier tier) {
  return tier == ValidationTier::quick ? "quick" : "full";
}

std::string to_string(CatalogueEntry::Check check) {
  return check == CatalogueEntry::Check::relative ? "relative" : "at_most";
}

std::string to_string(CatalogueEntry::Expect expect) {
  switch (expect) {
  case CatalogueEntry::Expect::compute:
    return "compute";
  case CatalogueEntry::Expect::finding:
    return "finding";
  case CatalogueEntry::Expect::skipped:
    return "skipped";
  }
  return "unknown";
}

namespace {

// InputError at `node` whose message starts with the entry id, so a user sees which figure.
[[noreturn]] void fail_entry(const YamlNode& node, const std::string& id, const std::string& what) {
  throw InputError(node.file(), node.line(), node.path(), "entry '" + id + "': " + what);
}

// An accuracy in percent: 0 and 100 or more are not accuracies a solve can aim at.
double read_accuracy_pct(const YamlNode& n, const std::string& id) {
  const double pct = n.as_double();
  if (!(pct > 0 && pct < 100))
    fail_entry(n, id, "accuracy_pct must be > 0 and < 100 (percent), got " + n.as_string());
  return pct;
}

// evaluate.fe: mesh scales per tier ({quick: [...], full: [...]}, coarse to fine) or an
// accuracy ({accuracy_pct: PCT or {quick: PCT, full: PCT}, quantity: NAME, start_scale: S,
// max_passes: N, max_unknowns: N}); either way `reason` says why.
void read_fe(const YamlNode& fe, CatalogueEntry& e, const Evaluator& evaluator) {
  fe.allow_keys({"quick", "full", "accuracy_pct", "quantity", "start_scale", "max_passes",
                 "max_unknowns", "reason"});
  if (!fe.has("reason"))
    fail_entry(fe, e.id, "evaluate.fe needs a reason: why this accuracy, or why fixed mesh scales");
  e.fe_reason = fe.at("reason").as_string();
  const auto acc = fe.find("accuracy_pct");
  if (!acc) {
    for (const char* key : {"quantity", "start_scale", "max_passes", "max_unknowns"})
      if (fe.has(key))
        fail_entry(fe.at(key), e.id,
                   std::string(key) + " applies to an FE accuracy: give accuracy_pct");
    return;
  }
  for (const char* tier : {"quick", "full"})
    if (fe.has(tier))
      fail_entry(fe.at(tier), e.id, "give mesh scales or accuracy_pct, not both");
  // An evaluator that reads only mesh scales would drop the accuracy silently.
  if (!evaluator.adapts)
    fail_entry(*acc, e.id,
               "evaluator " + e.evaluator + " runs at fixed mesh scales: give quick/full scales");
  FeAccuracy a;
  if (acc->is_map()) {
    acc->allow_keys({"quick", "full"});
    if (auto q = acc->find("quick"))
      a.quick_pct = read_accuracy_pct(*q, e.id);
    if (auto f = acc->find("full"))
      a.full_pct = read_accuracy_pct(*f, e.id);
  } else {
    a.quick_pct = a.full_pct = read_accuracy_pct(*acc, e.id);
  }
  const YamlNode q = fe.at("quantity");
  a.quantity = q.as_string();
  if (!e.case_file.empty()) {
    std::string why;
    if (!parse_adapt_quantity(a.quantity, read_case(e.case_file), why))
      fail_entry(q, e.id, why);
  }
  if (auto s = fe.find("start_scale"))
    a.start_scale = s->as_positive();
  if (auto m = fe.find("max_passes")) {
    a.max_passes = m->as_int();
    if (a.max_passes < 1)
      fail_entry(*m, e.id, "max_passes must be >= 1");
  }
  if (auto m = fe.find("max_unknowns"))
    a.max_unknowns = m->as_positive();
  e.fe_accuracy = a;
}

void read_evaluate(const YamlNode& ev, CatalogueEntry& e, const std::filesystem::path& folder) {
  const auto& registry = evaluator_registry();
  const YamlNode name = ev.at("evaluator");
  e.evaluator = name.as_string();
  const auto it = registry.find(e.evaluator);
  if (it == registry.end()) {
    std::string known;
    for (const auto& [k, v] : registry)
      known += (known.empty() ? "" : ", ") + k;
    fail_entry(name, e.id, "unknown evaluator '" + e.evaluator + "' (known: " + known + ")");
  }
  const Evaluator& evaluator = it->second;
  if (auto q = ev.find("quantity")) {
    e.evaluator_quantity = q->as_string();
    bool known = false;
    for (const auto& allowed : evaluator.quantities)
      known = known || allowed == e.evaluator_quantity;
    if (!known) {
      std::string list;
      for (const auto& allowed : evaluator.quantities)
        list += (list.empty() ? "" : ", ") + allowed;
      fail_entry(*q, e.id,
                 "unknown quantity '" + e.evaluator_quantity + "' for evaluator " + e.evaluator +
                     " (known: " + list + ")");
    }
  } else if (!evaluator.quantities.empty()) {
    fail_entry(ev, e.id, "missing evaluate.quantity for evaluator " + e.evaluator);
  }
  if (auto c = ev.find("case")) {
    const auto path = (folder / c->as_string()).lexically_normal();
    if (!std::filesystem::is_regular_file(path))
      fail_entry(*c, e.id, "case file not found: " + path.string());
    e.case_file = path.string();
  } else if (evaluator.needs_case) {
    fail_entry(ev, e.id, "evaluator " + e.evaluator + " needs evaluate.case");
  }
  for (const std::string key : {"reference_case"})
    if (auto c = ev.find(key)) {
      const auto path = (folder / c->as_string()).lexically_normal();
      if (!std::filesystem::is_regular_file(path))
        fail_entry(*c, e.id, "case file not found: " + path.string());
    }
  if (auto fe = ev.find("fe"))
    read_fe(*fe, e, evaluator);
  e.evaluate = ev;
}

CatalogueEntry read_entry(const YamlNode& n, const std::filesystem::path& folder) {
  CatalogueEntry e;
  e.line = n.line();
  e.id = n.at("id").as_string();
  n.allow_keys({"id", "source", "section", "quantity", "unit", "published", "tolerance_pct",
                "tolerance_reason", "check", "expect", "reason", "paper", "tier", "evaluate"});
  e.source = n.at("source").as_string();
  e.section = n.at("section").as_string();
  e.quantity = n.at("quantity").as_string();
  e.unit = n.get_string("unit", "");
  e.paper = n.get_string("paper", "");
  e.reason = n.get_string("reason", "");
  const std::string expect = n.get_string("expect", "compute");
  if (expect == "compute")
    e.expect = CatalogueEntry::Expect::compute;
  else if (expect == "finding")
    e.expect = CatalogueEntry::Expect::finding;
  else if (expect == "skipped")
    e.expect = CatalogueEntry::Expect::skipped;
  else
    fail_entry(n.at("expect"), e.id, "expect must be compute, finding or skipped");
  if (e.expect != CatalogueEntry::Expect::compute && e.reason.empty())
    fail_entry(n, e.id, "a " + expect + " entry must give its reason");
  if (auto p = n.find("published"))
    e.published = p->as_double();
  const std::string check = n.get_string("check", "relative");
  if (check == "relative")
    e.check = CatalogueEntry::Check::relative;
  else if (check == "at_most")
    e.check = CatalogueEntry::Check::at_most;
  else
    fail_entry(n.at("check"), e.id, "check must be relative or at_most");
  const std::string tier = n.get_string("tier", "quick");
  if (tier == "quick")
    e.tier = ValidationTier::quick;
  else if (tier == "full")
    e.tier = ValidationTier::full;
  else
    fail_entry(n.at("tier"), e.id, "tier must be quick or full");
  if (e.expect == CatalogueEntry::Expect::skipped)
    return e;
  if (!e.published)
    fail_entry(n, e.id, "missing published value");
  if (e.check == CatalogueEntry::Check::relative && *e.published == 0)
    fail_entry(n.at("published"), e.id, "a relative check needs a non-zero published value");
  if (e.check == CatalogueEntry::Check::at_most && e.unit != "%")
    fail_entry(n.at("check"), e.id, "an at_most check compares a percentage: unit must be %");
  e.tolerance_pct = n.at("tolerance_pct").as_non_negative();
  e.tolerance_reason = n.at("tolerance_reason").as_string();
  read_evaluate(n.at("evaluate"), e, folder);
  return e;
}

SourceCitation read_source(const YamlNode& n) {
  n.allow_keys({"file", "cite", "authors", "title", "venue", "year", "link", "note"});
  return {n.at("file").as_string(),  n.at("cite").as_string(),  n.at("authors").as_string(),
          n.at("title").as_string(), n.at("venue").as_string(), n.at("year").as_string(),
          n.get_string("link", ""),  n.get_string("note", "")};
}

// With a `sources` list, an entry citing a document the list lacks would reach the report
// without its citation: refuse it here, where the line is known.
void check_source_listed(const Catalogue& c, const YamlNode& n) {
  if (c.sources.empty())
    return;
  const CatalogueEntry& e = c.entries.back();
  for (const auto& s : c.sources)
    if (s.file == e.source)
      return;
  fail_entry(n.at("source"), e.id, "source '" + e.source + "' is not listed under sources");
}

} // namespace

Catalogue read_catalogue(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path, 0, "", "catalogue not found");
  const YamlNode root = YamlNode::load_file(path);
  root.allow_keys({"sources", "entries"});
  const auto folder = std::filesystem::path(path).parent_path();
  Catalogue c;
  c.file = path;
  if (auto sources = root.find("sources"))
    for (const YamlNode& n : sources->items())
      c.sources.push_back(read_source(n));
  std::set<std::string> ids;
  for (const YamlNode& n : root.at("entries").items()) {
    c.entries.push_back(read_entry(n, folder));
    check_source_listed(c, n);
    if (!ids.insert(c.entries.back().id).second)
      fail_entry(n.at("id"), c.entries.back().id, "duplicate id");
  }
  return c;
}

} // namespace magfem
