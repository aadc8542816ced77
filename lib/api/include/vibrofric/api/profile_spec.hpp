// Profiles as written (model.md, "Curved contacts (MDR)"): names and measured files parsed once,
// without a number type, then built at any precision by make_profile (the classes are in
// vibrofric/core/curved/profile.hpp).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "vibrofric/api/input_value.hpp"
#include "vibrofric/core/errors.hpp"
#include "vibrofric/core/curved/profile.hpp"

namespace vibrofric {

// A profile as written, without a number type (built at any precision by make_profile).
struct ProfileSpec {
  ProfileKind kind = ProfileKind::flat;
  std::string name;        // canonical: "flat", "power:2", "wearflat:0.5", "profile:FILE"
  InputValue parameter;    // N of power:N, λ of wearflat:λ (physical's λ = b²/(R A): computed)
  std::vector<Decimal> r, f;  // profile:FILE samples, as written
  InputValue height_unit;     // profile:FILE heights are divided by this (physical: A in metres); none: 1
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
  switch (spec.kind) {
    case ProfileKind::flat: return nullptr;
    case ProfileKind::power: return std::make_unique<PowerProfile<Real>>(spec.parameter.to<Real>(), spec.name);
    case ProfileKind::wearflat: return std::make_unique<WearFlatProfile<Real>>(spec.parameter.to<Real>(), spec.name);
    case ProfileKind::measured: {
      std::vector<Real> r, f;
      const Real unit = spec.height_unit.to<Real>();
      for (std::size_t j = 0; j < spec.r.size(); ++j) {
        r.push_back(spec.r[j].to<Real>());
        f.push_back(spec.height_unit.given() ? Real(spec.f[j].to<Real>() / unit) : spec.f[j].to<Real>());
      }
      return std::make_unique<MeasuredProfile<Real>>(std::move(r), std::move(f), spec.name);
    }
  }
  throw InputError("unknown profile kind");
}

}  // namespace vibrofric
