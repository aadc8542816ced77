// The tool's computations that are more than one evaluation, for every front end (the tool, the
// Python module): `physical` from SI inputs (Eqs. 1, 5, 14; curved indenters by MDR, model.md)
// and `trace`, n(φ) and s(φ) over one period (Fig. 2).
#pragma once
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/evaluate.hpp"

namespace vibrofric {

// Outputs as (name, decimal text), in the tool's order: shape, E_star_Pa, G_star_Pa, k_z_N_per_m
// and k_x_N_per_m (flat) or contact_radius_max_m (curved), lambda (wearflat), beta, gamma,
// u_mean_m (given F-N), mu_over_mu0, mu, F_N_mean_N, F_x_mean_N, beta_c, and for the flat punch
// contact_fraction and stick_fraction.
using PhysicalOutputs = std::vector<std::pair<std::string, std::string>>;

// `inputs` by the tool's flag names, values as typed: E1, nu1, E2, nu2, G1, G2 (optional), v0, f,
// A (zero-to-peak), u-mean or F-N (the mean normal load, γ then solves ⟨F_N⟩(γ) = F_N), mu0,
// shape (flat | sphere | cone | wearflat | profile:FILE, default flat) and its geometry: radius,
// R, half-angle (degrees), flat-radius. `options` gives the solver controls and escalation (its
// profile is set from the shape). InputError names the input as --NAME.
PhysicalOutputs physical_point(const WaveSpec& wave, const std::map<std::string, std::string>& inputs,
                               const Precision& precision, const BatchOptions& options = {});

// Rows (φ, n, s) over one period, φ ascending: `points` + 1 equally spaced phases, both ends of
// every stick phase and the contact boundaries (where n = s = 0 exactly), `digits` significant
// digits each (at digits plus guard digits of working precision).
std::vector<std::array<std::string, 3>> trace_rows(const WaveSpec& wave, const std::string& beta,
                                                   const std::string& gamma, int points, int digits);

}  // namespace vibrofric
