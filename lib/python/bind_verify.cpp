// Binds vibrofric.verify (the paper's claims decided, as `vibrofric verify --format json`) and the
// lists vibrofric.catalogue (wave names) and vibrofric.claims (claim keys).
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "common.hpp"
#include "vibrofric/verification/claims.hpp"

namespace vibrofric::python {

void bind_verify(py::module_& m) {
  m.def(
      "verify",
      [](const py::object& claim, const py::object& digits_obj) {
        const auto digits = optional_int(digits_obj, "digits");
        const int d = digits ? *digits : 50;
        if (d < min_verify_digits || d > max_verify_digits)
          throw InputError("digits = " + std::to_string(d) + ": expected " + std::to_string(min_verify_digits) + " to " +
                           std::to_string(max_verify_digits) + " (the range over which the verdicts are tested)");
        std::vector<ClaimCheck> checks;
        if (!claim.is_none() && !py::isinstance<py::str>(claim))
          throw py::type_error("claim = " + py_repr(claim) + ": expected a claim key such as 'eq17'");
        const std::string key = claim.is_none() ? std::string() : claim.cast<std::string>();
        {
          py::gil_scoped_release release;
          if (claim.is_none())
            checks = verify_claims(d);
          else
            checks.push_back(check_claim(key, d));
        }
        // The fields of the tool's JSON, in its order (for_each_field), plus digits; measured as
        // dicts {name, value, fields}.
        py::list out;
        for (const ClaimCheck& c : checks) {
          py::dict j;
          for_each_field(c, [&](const char* name, const auto& value) {
            using V = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<V, std::optional<std::string>>) {
              j[name] = value ? py::object(py::str(*value)) : py::none();
            } else if constexpr (std::is_same_v<V, std::vector<Measurement>>) {
              py::list measured;
              for (const auto& m : value) {
                py::dict fields;
                for (const auto& [key, text] : m.fields) fields[py::str(key)] = text;
                measured.append(py::dict("name"_a = m.name, "value"_a = m.value, "fields"_a = fields));
              }
              j[name] = measured;
            } else {
              j[name] = value;
            }
          });
          j["digits"] = c.digits;
          out.append(j);
        }
        return out;
      },
      "claim"_a = py::none(), "digits"_a = 50,
      R"doc(verify(claim=None, digits=50) -> list of dict

Decides the paper's claims (model.md, "The paper's claims that the suite verifies") with the
high-precision solver at `digits` (10 to 300) plus guard digits, as `vibrofric verify --format
json`: one dict per claim with key, id, source, statement, method, how, criterion, proof, worst,
verdict ('holds', 'holds approximately', 'fails'), scope, fails_where, corrected, cases,
deviation (decimal string), deviation_unit, corrected_deviation (None without a corrected
statement), measured (list of dicts: name, value as printed, and fields, its parts by name)
and digits. claim: one key ('eq17', 'eq24', ...);
None runs every claim (minutes). ValueError for an unknown key.
)doc");
}

void bind_catalogues(py::module_& m) {
  m.attr("catalogue") = py::cast(catalogue_names());
  py::list keys;
  for (const auto& c : claims_catalogue()) keys.append(c.key);
  m.attr("claims") = keys;
}

}  // namespace vibrofric::python
