// claims_json (claims.hpp): the catalogue's results as one JSON document, written with nlohmann.
#include <nlohmann/json.hpp>

#include <type_traits>

#include "vibrofric/verification/claims.hpp"

namespace vibrofric {

std::string claims_json(const std::vector<ClaimCheck>& checks, int digits) {
  nlohmann::ordered_json doc;
  doc["digits"] = digits;
  doc["claims"] = nlohmann::json::array();
  for (const auto& c : checks) {
    nlohmann::ordered_json j;
    for_each_field(c, [&](const char* name, const auto& value) {
      using V = std::decay_t<decltype(value)>;
      if constexpr (std::is_same_v<V, std::optional<std::string>>) {
        j[name] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
      } else if constexpr (std::is_same_v<V, std::vector<Measurement>>) {
        j[name] = nlohmann::json::array();
        for (const auto& m : value) {
          nlohmann::ordered_json fields = nlohmann::ordered_json::object();
          for (const auto& [key, text] : m.fields) fields[key] = text;
          j[name].push_back({{"name", m.name}, {"value", m.value}, {"fields", std::move(fields)}});
        }
      } else {
        j[name] = value;
      }
    });
    doc["claims"].push_back(std::move(j));
  }
  return doc.dump(1);
}

}  // namespace vibrofric
