#include "casefile/adapt_reader.hpp"

namespace magfem {

void read_adapt(const YamlNode& node, CaseSpec& c) {
  node.allow_keys({"accuracy_pct", "quantities", "max_passes", "max_unknowns"});
  AdaptSpec& a = c.adapt;
  a.line = node.line();
  const YamlNode acc = node.at("accuracy_pct");
  a.accuracy_pct = acc.as_double();
  // 100 % or more asks for nothing; 0 or less cannot be reached.
  if (!(a.accuracy_pct > 0 && a.accuracy_pct < 100))
    acc.fail("accuracy_pct must be between 0 and 100 (exclusive)");
  if (node.has("quantities"))
    for (const auto& q : node.at("quantities").items()) {
      std::string why;
      if (!parse_adapt_quantity(q.as_string(), c, why))
        q.fail(why);
      a.quantities.push_back(q.as_string());
    }
  a.max_passes = node.get_int("max_passes", a.max_passes);
  if (a.max_passes < 1)
    node.at("max_passes").fail("max_passes must be at least 1");
  if (node.has("max_unknowns"))
    a.max_unknowns = node.at("max_unknowns").as_positive();
}

} // namespace magfem
