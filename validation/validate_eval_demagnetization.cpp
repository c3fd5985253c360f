// Evaluator `demagnetization`: the minimum of B . m_hat over one magnet region of a case, as
// `magfem solve` reports it in summary.json's `demagnetization` block (postproc/
// demagnetization.hpp), for published worst-case working points (thesis sec. 4.4.3, Fig. 4.14).
// Parameters: `region` (the magnet), `case`, `fe` (mesh scales: the FE solve is the method).
#include "core/input_error.hpp"
#include "validation/validate_evaluators.hpp"

namespace magfem {

namespace {

const DemagnetizationCheck& region_check(const FeProbes& run, const std::string& region) {
  for (const auto& c : run.demagnetization)
    if (c.region == region)
      return c;
  throw std::runtime_error("no magnet region '" + region + "' in the case");
}

EvalResult min_B_along_M(const EvalContext& ctx) {
  const std::string region = ctx.text("region", "");
  if (region.empty())
    throw InputError(ctx.entry.evaluate ? ctx.entry.evaluate->file() : "", ctx.entry.line,
                     "evaluate.region", "entry '" + ctx.entry.id + "': missing parameter");
  EvalResult r;
  const auto scales = ctx.fe_scales();
  set_fe_values(r, scales, [&](double s) {
    const auto run = fe_probes(ctx.cache, ctx.entry.case_file, s);
    const auto& c = region_check(*run, region);
    auto d = run->describe();
    d["min_B_along_M_T"] = c.min_B_along_M_T;
    d["at_mm"] = {c.at_m.x() * 1e3, c.at_m.y() * 1e3, c.at_m.z() * 1e3};
    r.details["fe"].push_back(d);
    return c.min_B_along_M_T;
  });
  r.method = "FE solve of the case (magfem solve): the minimum over region '" + region +
             "' of B . m_hat, read at the vertices of its elements from the element field "
             "(summary.json demagnetization).";
  return r;
}

} // namespace

void register_demagnetization(std::map<std::string, Evaluator>& r) {
  r["demagnetization"] = {"demagnetization", {"min_B_along_M"}, true, min_B_along_M};
}

} // namespace magfem
