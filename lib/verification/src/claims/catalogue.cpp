// The catalogue of claims (claims.hpp), in the order of model.md's table.
#include <stdexcept>

#include "check.hpp"

namespace vibrofric {

std::string verdict_name(Verdict v) {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::holds_approximately: return "holds approximately";
    case Verdict::fails: return "fails";
  }
  return "?";
}

std::string verdict_text(const ClaimCheck& c) {
  if (c.verdict == Verdict::holds_approximately) return verdict_name(c.verdict);
  return verdict_name(c.verdict) + " (" + c.certification + ")";
}

const std::string& Measurement::field(const std::string& key) const {
  for (const auto& [k, v] : fields)
    if (k == key) return v;
  throw InputError("measurement '" + name + "' has no field '" + key + "'");
}

namespace {
const char* const kHighPrecision = "high-precision comparison";
const char* const kProofAndHP = "symbolic proof + high-precision comparison";
const char* const kDerivationAndHP = "written derivation + high-precision comparison";
const char* const kTiming = "high-precision comparison + CPU timing";
}  // namespace

const std::vector<ClaimEntry>& claims_catalogue() {
  using namespace claims;
  static const std::vector<ClaimEntry> list{
      {"eq6", "Eq. 6", "paper", "beta >= beta_c  =>  mu = mu0 (no stick-slip); stick for every smaller beta", kProofAndHP,
       "proofs/eq6_beta_c.md", eq6},
      {"eq13", "Eq. 13", "paper", "no jumping: mu/mu0 = 1 - alpha Psi_w(beta), Psi_w independent of gamma", kProofAndHP,
       "proofs/eq13_gamma_independence.md", eq13},
      {"eq17", "Eq. 17", "paper", "Psi_str = 1 - beta/2, Psi_stl = 2/(2+beta), Psi_tri = (4-beta)/(4+beta)", kProofAndHP,
       "proofs/eq17_triangular_psi.md", eq17},
      {"eq18", "Eq. 18", "paper", "triangular waves: mu(beta, gamma < 1) = mu(beta, gamma = 1) = mu0 (1 - Psi_w(beta))",
       kProofAndHP, "proofs/eq18_19_clipping.md", eq18},
      {"eq19", "Eq. 19", "paper", "jumping: mu_str = mu0 beta/2, mu_stl = mu0 beta/(2+beta), mu_tri = mu0 2beta/(4+beta)",
       kProofAndHP, "proofs/eq18_19_clipping.md", eq19},
      {"eq20-21", "Eq. 20-21", "paper", "square wave: mu(beta, gamma) = mu0 (1 - Psi_sqr(xi)), xi_sqr = 2 beta/(1+gamma)",
       kProofAndHP, "proofs/eq21_22_square.md", eq20_21},
      {"eq22", "Eq. 22", "paper", "square wave: mu/mu0 = beta/(4(1+gamma)) for beta < 2(1+gamma), else 1 - (1+gamma)/beta",
       kProofAndHP, "proofs/eq21_22_square.md", eq22},
      {"eq23", "Eq. 23", "paper",
       "harmonic: asymptotically mu(beta, gamma) = mu(xi_2, gamma0), xi_2 = beta sqrt((1+gamma0)/(1+gamma)), gamma0 = -0.3",
       kHighPrecision, "", eq23},
      {"eq24", "Eq. 24", "paper",
       "power law of order n: mu(beta, gamma) = mu(xi_n, gamma0), xi_n = beta ((1+gamma0)/(1+gamma))^(1/n)", kProofAndHP,
       "proofs/eq24_power_remap.md", eq24},
      {"sec3", "Sec. 3", "paper", "jumping case: the static coefficient of friction is zero", kDerivationAndHP,
       "proofs/sec3_static.md", sec3},
      {"fig3", "Fig. 3", "paper", "square-wave mu(beta) for 11 values of gamma from 1 to -1 (Eq. 22)", kHighPrecision,
       "proofs/eq21_22_square.md", fig3},
      {"fig4-bunching", "Fig. 4a", "paper",
       "harmonic: for gamma in (-0.2, 1) mu depends only weakly on gamma, the curves bunch closely together",
       kHighPrecision, "", fig4_bunching},
      {"fig4-minimum", "Fig. 4b", "paper",
       "harmonic: mu decreases from gamma = 1 to about 0.6, then increases again down to -1", kHighPrecision, "",
       fig4_minimum},
      {"fig4-scaling", "Fig. 4c", "paper",
       "harmonic: from about gamma = -0.3 on, mu is roughly parabolic and follows Eq. 23 (black dots)", kHighPrecision,
       "", fig4_scaling},
      // model.md's claims table, the remaining statements of the paper (statements.cpp).
      {"eqs7-13", "Eqs. 7-13", "paper",
       "'after expanding and rearranging', Eqs. 7-10 give Delta F_x = mu0 k_z A Psi_w(beta) (Eqs. 11-12) and mu = mu0 (1 - "
       "alpha Psi_w(beta)) (Eq. 13)",
       kProofAndHP, "proofs/eqs7_13_reduction.md", eqs7_13},
      {"eq6-jumping", "Eq. 6, jumping range", "paper",
       "read with the unclipped w of Eq. 2 (beta_c = max w'): for beta < beta_c friction 'is reduced by some amount', also "
       "in the jumping range",
       kHighPrecision, "proofs/beta_c_sine.md", eq6_jumping},
      {"entanglement", "Sec. 3, entanglement", "paper",
       "in the jumping range the simplicity of Eq. 13 can no longer be maintained: mu != mu0 (1 - alpha Psi_w(beta)), alpha "
       "and beta become entangled (Conclusions)",
       kHighPrecision, "", entanglement},
      {"continuity", "Sec. 3.1, continuity", "paper",
       "the area ratio (mu) changes continuously as the waveform is clipped from below by increasingly large amplitudes",
       kDerivationAndHP, "proofs/sec3_continuity.md", continuity},
      {"uniqueness", "Sec. 3.1, uniqueness", "paper",
       "the triangular waves have the unique property that clipping the waveform does not affect the coefficient of friction",
       kProofAndHP, "proofs/sec3_uniqueness_convexity.md", uniqueness},
      {"convexity", "Sec. 3.2, convexity", "paper",
       "for a self-similar waveform, convexity ensures that stick is precipitated in the point of first contact",
       kDerivationAndHP, "proofs/sec3_uniqueness_convexity.md", convexity},
      {"eq23-range", "Sec. 3.2, Eq. 23 range", "paper",
       "the harmonic scaling (Eq. 23) will not be valid for values of gamma close to 1", kHighPrecision, "", eq23_range},
      {"fig2", "Fig. 2", "paper",
       "F_x <= F_slip = mu0 F_z everywhere; the stick phases are straight segments, the slip phases follow mu0 F_z",
       kHighPrecision, "", fig2},
      {"beta-c", "beta_c", "model.md (correction)", "beta_c = 2 pi (sine), 4 (triangle), 2 (str), 4p (power:p), infinite (stl, square)",
       kDerivationAndHP, "proofs/beta_c_sine.md", beta_c_table},
      // Curved contacts (model.md, "Curved contacts (MDR)"); derivations in lib/verification/src/claims/curved.cpp.
      {"scope-wearflat", "Abstract, scope (wear flat)", "paper",
       "the exact solutions hold for a flat-ended cylinder or a curved shape with a wear flat (sphere with a wear flat: "
       "mu = the flat punch's mu)",
       kDerivationAndHP, "proofs/curved_closed_forms.md", scope_wearflat},
      {"scope-numerics", "Abstract, scope (numerics)", "paper",
       "the adopted methodology also enables efficient numerical solution in more general cases (curved contacts by "
       "MDR: a sphere under harmonic oscillation to the requested digits; the CPU time is measured, not judged)",
       kTiming, "", scope_numerics},
      {"curved-eq6-sec3", "Eq. 6 + Sec. 3, curved", "model.md (extension)",
       "curved contacts (MDR): beta >= beta_c(gamma) of the central spring => mu = mu0, stick below; static "
       "coefficient mu_s = int (gamma - 1 - sigma)_+ dx / int N dx: zero iff the central spring jumps (gamma <= 1)",
       kDerivationAndHP, "", curved_eq6_sec3},
      {"curved-power-flat", "power:N -> flat", "model.md (extension)",
       "power-law profiles sigma = x^N tend to the flat punch as N -> infinity", kDerivationAndHP,
       "proofs/curved_closed_forms.md", curved_power_flat},
      // Rig dynamics (model.md, "Rig dynamics: mass and system stiffness") and the abstract of the
      // series' Part II; checks in lib/verification/src/claims/rig.cpp.
      {"rig-limits", "Rig dynamics, limits", "model.md (extension)",
       "continuous n: a massless body (Omega -> infinity) gives mu = g_w(beta kappa/(1+kappa), gamma), the paper's "
       "model at the series stiffness, as O(1/Omega); not where n jumps down in contact (square wave, gamma > 1)",
       kHighPrecision, "", rig_limits},
      {"part2-limits", "Part II, abstract: limits", "Part II (abstract)",
       "the limiting cases of a very stiff and a very soft system reproduce earlier results", kHighPrecision, "",
       part2_limits},
      {"part2-resonance", "Part II, abstract: resonance", "Part II (abstract)",
       "a new resonant case eliminates the critical sliding velocity (friction is reduced at every velocity)",
       kHighPrecision, "", part2_resonance},
      // In-plane oscillation (model.md, "In-plane and combined oscillation"), the longitudinal case;
      // checks in lib/verification/src/claims/inplane.cpp.
      {"inplane-rigid", "In-plane, rigid limit", "model.md (extension)",
       "longitudinal oscillation at a constant normal force, rigid contact (a -> infinity at fixed xi = v0/(2 pi f u)): "
       "mu = (2/pi) arcsin xi below the critical velocity xi = 1 and mu0 above it",
       kHighPrecision, "", inplane_rigid},
      {"inplane-ratchet", "In-plane, ratchet", "model.md (extension)",
       "normal and longitudinal oscillation a quarter period apart propel the body: at beta = 0, n = max(0.5 + sin, 0), "
       "a = 1, P = 1/4, mu = int s / int n ~ -0.5364",
       kHighPrecision, "", inplane_ratchet},
      {"inplane-combined", "Review: combined oscillation", "review (Front. Mech. Eng. 2020)",
       "normal and longitudinal oscillation together reduce friction more than either alone, at the right phase",
       kHighPrecision, "", inplane_combined},
      {"inplane-transverse", "In-plane, transverse rigid limit", "model.md (extension)",
       "transverse oscillation at a constant normal force, rigid contact (a -> infinity at fixed xi): "
       "mu = (2/pi) xi/sqrt(1+xi^2) K(1/sqrt(1+xi^2)), no critical velocity",
       kHighPrecision, "", inplane_transverse},
  };
  return list;
}

namespace claims {
const ClaimEntry& entry(const std::string& key) {
  for (const auto& e : claims_catalogue())
    if (e.key == key) return e;
  throw std::logic_error("claims: no catalogue entry '" + key + "'");
}
}  // namespace claims

ClaimCheck check_claim(const std::string& key, int digits) {
  std::string keys;
  for (const auto& e : claims_catalogue()) {
    if (e.key == key) {
      PrecisionScope scope(static_cast<unsigned>(digits + guard_digits(digits)));
      return e.check(digits);
    }
    keys += (keys.empty() ? "" : ", ") + e.key;
  }
  throw InputError("claim '" + key + "': expected one of " + keys);
}

std::vector<ClaimCheck> verify_claims(int digits) {
  std::vector<ClaimCheck> out;
  for (const auto& e : claims_catalogue()) out.push_back(check_claim(e.key, digits));
  return out;
}

}  // namespace vibrofric
