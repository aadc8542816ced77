// Profiles as written (model.md, "Curved contacts (MDR)"): names and measured files parsed once,
// without a number type, then built at any precision by make_profile (the classes are in
// vibrofric/core/profile.hpp).
#pragma once
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/profile.hpp"

namespace vibrofric {

// A profile as written, without a number type (built at any precision by make_profile).
struct ProfileSpec {
  ProfileKind kind = ProfileKind::flat;
  std::string name;       // canonical: "flat", "power:2", "wearflat:0.5", "profile:FILE"
  std::string parameter;  // N of power:N, λ of wearflat:λ, as written
  std::optional<mpfr> parameter_value;  // computed (physical's λ = b²/(R A)): used instead, rounded
                                        // once to each type; `parameter` then only names it
  std::vector<std::string> r, f;  // profile:FILE samples, as written
  std::string height_unit = "1";   // profile:FILE heights are divided by this (physical: A in metres)
};

// Accepts flat, power:N (N ≥ 1), sphere, cone, wearflat:LAMBDA (λ > 0), profile:FILE.
// Throws InputError quoting the text otherwise (also for bad files: see parse_profile_file).
ProfileSpec parse_profile(const std::string& text);

// A wear flat of computed λ (physical's b²/(R A)), with the decisions parse_profile makes on a
// typed one (λ > 0, within double's range); λ is the value, `text` only names it.
ProfileSpec wear_flat_profile(const mpfr& lambda, const std::string& text);

// Reads a measured profile: lines 'r f' ('#' comments, blank lines ignored; comma, semicolon or
// whitespace between the two fields), r strictly increasing from r = 0, f(0) = 0, f
// non-decreasing and convex (slopes non-decreasing), at least two samples, at most 100000.
ProfileSpec parse_profile_file(const std::string& path, const std::string& text);

template <class Real>
std::unique_ptr<Profile<Real>> make_profile(const ProfileSpec& spec) {
  auto number = [](const std::string& text) -> Real {
    if constexpr (std::is_same_v<Real, double>) return std::strtod(text.c_str(), nullptr);
    else if constexpr (std::is_same_v<Real, long double>) return std::strtold(text.c_str(), nullptr);
    else return Real(text);
  };
  const auto parameter = [&]() -> Real {
    if (spec.parameter_value) return detail::rounded<Real>(*spec.parameter_value);
    return number(spec.parameter);
  };
  switch (spec.kind) {
    case ProfileKind::flat: return nullptr;
    case ProfileKind::power: return std::make_unique<PowerProfile<Real>>(parameter(), spec.name);
    case ProfileKind::wearflat: return std::make_unique<WearFlatProfile<Real>>(parameter(), spec.name);
    case ProfileKind::measured: {
      std::vector<Real> r, f;
      const Real unit = number(spec.height_unit);
      for (std::size_t j = 0; j < spec.r.size(); ++j) {
        r.push_back(number(spec.r[j]));
        f.push_back(spec.height_unit == "1" ? number(spec.f[j]) : Real(number(spec.f[j]) / unit));
      }
      return std::make_unique<MeasuredProfile<Real>>(std::move(r), std::move(f), spec.name);
    }
  }
  throw InputError("unknown profile kind");
}

}  // namespace vibrofric
