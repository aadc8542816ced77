// claims_json (claims.hpp): the catalogue's results as one JSON document, written with nlohmann.
#include <nlohmann/json.hpp>

#include "vibrofric/verification/claims.hpp"

namespace vibrofric {

std::string claims_json(const std::vector<ClaimCheck>& checks, int digits) {
  nlohmann::ordered_json doc;
  doc["digits"] = digits;
  doc["claims"] = nlohmann::json::array();
  for (const auto& c : checks) {
    nlohmann::ordered_json j;
    j["key"] = c.key;
    j["id"] = c.id;
    j["source"] = c.source;
    j["statement"] = c.statement;
    j["method"] = c.method;
    j["how"] = c.how;
    j["criterion"] = c.criterion;
    j["proof"] = c.proof;
    j["worst"] = c.worst;
    j["verdict"] = verdict_name(c.verdict);
    j["scope"] = c.scope;
    j["fails_where"] = c.fails_where;
    j["corrected"] = c.corrected;
    j["cases"] = c.cases;
    j["deviation"] = c.deviation_text;
    j["deviation_unit"] = c.deviation_unit;
    j["corrected_deviation"] = c.corrected_deviation ? nlohmann::json(c.corrected_deviation_text) : nlohmann::json(nullptr);
    j["measured"] = nlohmann::json::array();
    for (const auto& m : c.measured) j["measured"].push_back({m.name, m.value});
    doc["claims"].push_back(std::move(j));
  }
  return doc.dump(1);
}

}  // namespace vibrofric
