// Sec. 3.1 "uniqueness" and Sec. 3.2 "convexity".
// (a) Clipping invariance mu(beta, gamma) = mu(beta, 1) on -1 < gamma <= 1 holds for every wave whose
//     teeth are linear from the global minimum -1 up to the global maximum +1 and linear back down
//     (any slopes, several teeth per period): general symbolic proof per tooth (similarity, c^2
//     scaling), then the engine on a two-tooth non-triangular wave (closed form, all beta regimes),
//     asymmetric triangles, and controls that must NOT be invariant (flat top, local minimum above
//     -1, kink in the rising flank).
// (b) Convexity: a concave cap (non-increasing slope after first contact) puts the stick onset at
//     first contact; otherwise it can start inside the contact: piecewise-linear example (engine,
//     exact) and the sine at gamma = 1/2, beta = 6 (high-precision numerics, explicit antiderivatives).
#include "engine.hpp"
using namespace proofs;

namespace {

// Piecewise-linear periodic wave through the points (x_i, w_i), x_0 = 0 < x_1 < ... < 1, closing at
// (1, w_0); shift is added to every value (normalisation to zero mean).
Wave from_points(const std::vector<std::pair<ex, ex>>& p, const ex& shift = 0) {
  Wave w;
  const size_t N = p.size();
  for (size_t i = 0; i < N; ++i) {
    ex x0 = p[i].first, x1 = i + 1 < N ? p[i + 1].first : ex(1);
    ex a = p[i].second + shift, b = (i + 1 < N ? p[i + 1].second : p[0].second) + shift;
    w.push_back({x0, x1, a, normal((b - a) / (x1 - x0))});
  }
  return w;
}
Wave samples(const std::vector<ex>& s, const ex& shift = 0) {
  std::vector<std::pair<ex, ex>> p;
  for (size_t i = 0; i < s.size(); ++i) p.push_back({numeric(int(i), int(s.size())), s[i]});
  return from_points(p, shift);
}
ex wave_mean(const Wave& w) {
  ex m = 0;
  for (auto& s : w) m += (s.x1 - s.x0) * (2 * s.a + s.m * (s.x1 - s.x0)) / 2;
  return normal(m);
}
std::string wave_text(const Wave& w) {
  std::ostringstream os;
  for (auto& s : w) os << "[" << s.x0 << "," << s.x1 << "): " << s.a << " slope " << s.m << "  ";
  return os.str();
}

// ---- regimes that are boxes in (beta, gamma); beta1 < 0 means beta -> infinity.
// The engine proves a branch condition when all its factors are affine; on a box a factor that is
// multilinear (degree <= 1 in beta and in gamma separately) is affine on every axis-parallel line,
// so its extremes are at the corners (and along the beta ray, the sign of its beta-coefficient at
// the two gamma edges); >= 0 there and not identically 0 => > 0 on the open box. Conditions the
// engine could only sample are re-proved this way.
struct Box { std::string text; numeric b0, b1, g0, g1; };
struct BoxLog { size_t engine_proved = 0, box_proved = 0; std::vector<std::string> sampled; std::vector<bool> seen; };
BoxLog& boxlog() { static BoxLog l; return l; }

Regime box_regime(const Box& bx) {
  std::vector<std::pair<numeric, numeric>> v, r;
  bool ray = bx.b1 < 0;
  v.push_back({bx.b0, bx.g0});
  if (bx.g1 != bx.g0) v.push_back({bx.b0, bx.g1});
  if (!ray && bx.b1 != bx.b0) {
    if (bx.g1 != bx.g0) v.push_back({bx.b1, bx.g1});
    v.push_back({bx.b1, bx.g0});
  }
  if (ray) r.push_back({1, 0});
  return make_regime(bx.text, v, r);
}

bool multilinear_factor_sign(const ex& f, const Box& bx, int& out) {
  ex fe = expand(f);
  if (!fe.is_polynomial(lst{B(), G()}) || fe.degree(B()) > 1 || fe.degree(G()) > 1) return false;
  std::vector<ex> vals;
  std::vector<numeric> gs = {bx.g0, bx.g1};
  for (auto& gv : gs) {
    vals.push_back(fe.subs(lst{B() == bx.b0, G() == gv}));
    if (bx.b1 < 0) vals.push_back(fe.coeff(B(), 1).subs(G() == gv));  // direction of the beta ray
    else vals.push_back(fe.subs(lst{B() == bx.b1, G() == gv}));
  }
  bool pos = true, neg = true;
  for (auto& v : vals) {
    if (!is_a<numeric>(v)) return false;
    int s = sgn(ex_to<numeric>(v));
    if (s < 0) pos = false;
    if (s > 0) neg = false;
  }
  if (pos && neg) { out = 0; return true; }
  if (pos) { out = 1; return true; }
  if (neg) { out = -1; return true; }
  return false;
}
bool box_sign(const ex& p, const Box& bx, int& out) {
  // A zero factor is not a decided sign here (the condition would not be strict).
  return sign_by_factors(p, [&](const ex& base, int& fs) { return multilinear_factor_sign(base, bx, fs) && fs != 0; }, out);
}

// Run the engine on a box regime (gamma or beta fixed when the box is degenerate in it).
Result go(const Wave& w, const Box& bx, const std::string& label, bool print = true) {
  Regime R = box_regime(bx);
  size_t before = condition_log().size();
  ex gv = bx.g0 == bx.g1 ? ex(bx.g0) : ex(G());
  ex bv = bx.b0 == bx.b1 ? ex(bx.b0) : ex(B());
  Result r = run(clip(w, gv, R), bv, R);
  boxlog().seen.resize(condition_log().size(), false);
  for (size_t i = before; i < condition_log().size(); ++i) {
    boxlog().seen[i] = true;
    const Condition& c = condition_log()[i];
    if (c.proved) { ++boxlog().engine_proved; continue; }
    int sn, sd;
    if (box_sign(numer(c.e), bx, sn) && box_sign(denom(c.e), bx, sd) && sn * sd == c.sign) ++boxlog().box_proved;
    else boxlog().sampled.push_back(label + ": " + c.what + ": " + ex_to_string(c.e));
  }
  if (print) print_run(label, r, R);
  return r;
}

bool has_first_contact_onset(const Result& r) {
  for (auto& e : r.events) if (e.kind.find("first contact") != std::string::npos) return true;
  return false;
}

// ---- numerics for the sine (GiNaC evalf at Digits = 50)
numeric num(const ex& e) {
  ex v = evalf(e);
  if (!is_a<numeric>(v)) throw std::runtime_error("not numeric: " + ex_to_string(e));
  return ex_to<numeric>(v);
}

// Root of f(PHI()) on [lo, hi] where f changes sign: plain bisection (exact rational midpoints, f by
// evalf). Deterministic; GiNaC's fsolve was seen to loop on these functions in some runs.
numeric bisect(const ex& f, numeric lo, numeric hi) {
  auto sg = [&](const numeric& x) { return sgn(num(f.subs(PHI() == x))); };
  const int slo = sg(lo);
  if (slo == 0) return lo;
  if (sg(hi) != -slo) throw std::runtime_error("bisect: no sign change on the bracket");
  for (int k = 0; k < 180; ++k) {  // width (hi - lo) 2^-180 < 1e-54
    numeric mid = (lo + hi) / 2;
    int sm = sg(mid);
    if (sm == 0) return mid;
    (sm == slo ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

}  // namespace

int main() {
  Checker ck;
  const ex b = B(), g = G();

  // the box prover used for the engine's bilinear branch conditions (see Box): it must prove the trapezoid's
  // condition on 4 < beta < 8 and must refuse it on 0 < beta < 8, where it changes sign
  {
    ex c = 1 + g - b * (3 + g) / 8;
    int s1 = 0, s2 = 0;
    bool p1 = box_sign(c, Box{"", 4, 8, -1, 1}, s1), p2 = box_sign(c, Box{"", 0, 8, -1, 1}, s2);
    ck.ok(p1 && s1 < 0, "box prover: 1 + gamma - beta (3 + gamma)/8 < 0 on 4 < beta < 8, -1 < gamma < 1");
    ck.ok(!p2, "box prover refuses the same factor on 0 < beta < 8 (it changes sign there)");
  }

  // =========================================================== (a) general per-tooth proof
  std::cout << "== (a) one linear tooth of height H (contact part at level gamma: H = 1 + gamma)\n";
  symbol a("a"), bs("b"), H("H"), x("x"), lam("lambda"), d("d"), eps("eps");
  // n rises with slope a from first contact (x = 0) to the peak H at x = H/a, falls with slope b
  // to 0 at xe = H/a + H/b; s = 0 before (in the air, s <= n = 0 and s >= 0).
  const ex xp = H / a, xe = H / a + H / bs;
  const ex rise = a * x, fall = H - bs * (x - xp);
  auto tooth = [&](const ex& Hv, ex& N, ex& S, ex& x2) {
    ex rs = rise.subs(H == Hv), fs = fall.subs(H == Hv), xpv = xp.subs(H == Hv), xev = xe.subs(H == Hv);
    N = normal(integral(x, 0, xpv, rs).eval_integ() + integral(x, xpv, xev, fs).eval_integ());
    // beta < a: stick from first contact (n' = a > beta), ramp beta x, until it meets the falling flank
    x2 = normal(lsolve(b * x == fs, x));
    S = normal(integral(x, 0, x2, b * x).eval_integ() + integral(x, x2, xev, fs).eval_integ());
  };
  ex N, S, x2;
  tooth(H, N, S, x2);
  std::cout << "     int n = " << factor(N) << ",  stick end x2 = " << factor(x2) << ",  int s = " << factor(S) << "\n";
  ck.zero(x2 - xp - H * (a - b) / (a * (b + bs)), "x2 - H/a = H (a - beta)/(a (beta + b)) > 0 for beta < a: the ramp meets the falling flank");
  ck.zero(xe - x2 - H * b * (a + bs) / (a * bs * (b + bs)), "xe - x2 = H beta (a + b)/(a b (beta + b)) > 0: before the contact ends");
  ck.zero(expand((rise - b * x) - (a - b) * x), "n - ramp = (a - beta) x >= 0 on the rising flank (linear down to 0 at x2 on the falling one)");
  ex Nl, Sl, x2l;
  tooth(lam * H, Nl, Sl, x2l);
  ck.zero(Nl - pow(lam, 2) * N, "int n scales by lambda^2 when H -> lambda H");
  ck.zero(Sl - pow(lam, 2) * S, "int s scales by lambda^2 when H -> lambda H (beta < a)");
  const ex rho = normal(S / N);
  std::cout << "     per-tooth ratio int s / int n = " << factor(rho) << "\n";
  ck.zero(diff(rho, H), "per-tooth ratio does not depend on H (hence not on gamma)");
  ck.zero(rho - b * (a + bs) / (a * (b + bs)), "per-tooth ratio = beta (a + b)/(a (beta + b)) for beta < a (= 1 for beta >= a: no stick)");
  // the clipped tooth is the gamma = 1 tooth scaled by c = (1 + gamma)/2 in phase (about the peak) and in n
  {
    symbol y("y"), c("c");
    ex n1r = a * y, n1f = 2 - bs * (y - 2 / a);  // gamma = 1 tooth, H = 2, y from first contact
    ex Hg = 2 * c;
    ck.zero(expand(c * n1r.subs(y == y / c) - rise.subs(lst{x == y, H == Hg})), "rising flank at level gamma = c * (gamma = 1 rising flank)(y/c), c = (1 + gamma)/2 (same slope)");
    ck.zero(expand(c * n1f.subs(y == y / c) - fall.subs(lst{x == y, H == Hg})), "falling flank at level gamma = c * (gamma = 1 falling flank)(y/c) (same slope)");
    // in the original phase: first contact at x_p - (1 + gamma)/a, contact end x_p + (1 + gamma)/b, x_p the peak
    ck.zero((xp - xe).subs(H == Hg) - c * (xp - xe).subs(H == 2), "contact interval = c * (gamma = 1 interval), about the peak");
  }
  // limits: the catalogue's triangular waves (Eq. 19) as special teeth
  ck.zero(rho.subs(lst{a == 4, bs == 4}) - 2 * b / (4 + b), "a = b = 4 (tri): ratio = 2 beta/(4 + beta) (Eq. 19)");
  ck.zero(normal(normal(rho.subs(bs == 1 / eps)).subs(eps == 0)).subs(a == 2) - b / 2, "b -> infinity, a = 2 (str): ratio = beta/2 (Eq. 19)");
  ck.zero(normal(normal(rho.subs(a == 1 / eps)).subs(eps == 0)).subs(bs == 2) - b / (2 + b), "a -> infinity, b = 2 (stl): ratio = beta/(2 + beta) (Eq. 19)");
  // asymmetric triangle, peak at phi = d: a = 2/d, b = 2/(1 - d), symbolic d
  const ex rho_d = normal(rho.subs(lst{a == 2 / d, bs == 2 / (1 - d)}));
  ck.zero(rho_d - b / ((1 - d) * b + 2), "asymmetric triangle, peak at symbolic d: mu/mu0 = beta/((1 - d) beta + 2) for beta < 2/d");
  // several teeth with the same H = 1 + gamma: mu = sum S_k / sum N_k, independent of H
  {
    ex SN = 0, SS = 0;
    for (int k = 1; k <= 3; ++k) {
      symbol ak("a" + std::to_string(k)), bk("b" + std::to_string(k));
      SN += N.subs(lst{a == ak, bs == bk});
      SS += (k == 3 ? N : S).subs(lst{a == ak, bs == bk});  // tooth 3 with beta >= a3: no stick, s = n
    }
    ck.zero(diff(normal(SS / SN), H), "three teeth (slopes a_k, b_k; tooth 3 without stick), common H: sum int s / sum int n independent of H");
    // a tooth with a lower peak p < 1 has H_k = p + gamma: the weights change with gamma
    symbol p("p");
    ex S1 = S.subs(lst{a == 10, bs == 10}), N1 = N.subs(lst{a == 10, bs == 10});
    ex S2 = S.subs(lst{a == 5, bs == 10, H == H - 1 + p}), N2 = N.subs(lst{a == 5, bs == 10, H == H - 1 + p});
    ck.nonzero(diff(normal((S1 + S2) / (N1 + N2)), H), "second tooth with peak p < 1 (H2 = p + gamma) and different slopes: invariant");
    ex S3 = S.subs(lst{a == 10, bs == 10, H == H - 1 + p}), N3 = N.subs(lst{a == 10, bs == 10, H == H - 1 + p});
    ck.zero(diff(normal((S1 + S3) / (N1 + N3)), H), "remark: second tooth with peak p < 1 but the same slopes: still invariant (equal per-tooth ratios)");
  }

  // =========================================================== (a) the two-tooth wave, engine
  std::cout << "== (a) two-tooth wave through the samples (-1, 1, -1, 0, 1), period 5 samples\n";
  Wave two = samples({-1, 1, -1, 0, 1});
  std::cout << "     pieces: " << wave_text(two) << "\n";
  ck.zero(wave_mean(two), "two-tooth wave: zero mean (min -1, max 1)");
  const ex m1 = 13 * b / (50 + 5 * b), m2 = (30 + 7 * b) / (50 + 5 * b);
  // prediction of the per-tooth theorem: teeth (a, b) = (10, 10) and (5, 10), common H
  {
    ex SA = S.subs(lst{a == 10, bs == 10}), NA = N.subs(lst{a == 10, bs == 10});
    ex SB = S.subs(lst{a == 5, bs == 10}), NB = N.subs(lst{a == 5, bs == 10});
    ck.zero(normal((SA + SB) / (NA + NB)) - m1, "per-tooth theorem: 0 < beta < 5: mu/mu0 = 13 beta/(50 + 5 beta)");
    ck.zero(normal((SA + NB) / (NA + NB)) - m2, "per-tooth theorem: 5 <= beta < 10: mu/mu0 = (30 + 7 beta)/(50 + 5 beta)");
  }
  struct BR { numeric b0, b1; ex mu; int sticks; std::string txt; };
  std::vector<BR> branges = {{0, 5, m1, 2, "0 < beta < 5"}, {5, 10, m2, 1, "5 < beta < 10"}, {10, -1, ex(1), 0, "beta > 10"},
                             {5, 5, m1.subs(b == 5), 1, "beta = 5"}, {10, 10, ex(1), 0, "beta = 10"}};
  struct GR { numeric g0, g1; std::string txt; };
  std::vector<GR> granges = {{-1, 0, "-1 < gamma < 0"}, {0, 0, "gamma = 0"}, {0, 1, "0 < gamma < 1"}, {1, 1, "gamma = 1"}};
  for (auto& br : branges) {
    ex mu_ref;
    bool all = true, allind = true, sticks = true;
    for (auto& gr : granges) {
      Box bx{br.txt + ", " + gr.txt, br.b0, br.b1, gr.g0, gr.g1};
      Result r = go(two, bx, "two-tooth");
      all = all && normal(r.mu - br.mu).is_zero();
      allind = allind && normal(diff(r.mu, G())).is_zero();
      sticks = sticks && r.sticks == br.sticks;
      if (gr.g0 == 1) mu_ref = r.mu;
    }
    ck.ok(all, "two-tooth, " + br.txt + ": mu/mu0 = " + ex_to_string(br.mu) + " on -1 < gamma < 0, gamma = 0, 0 < gamma < 1 and gamma = 1");
    ck.ok(allind, "two-tooth, " + br.txt + ": d mu/d gamma = 0 on every gamma range");
    ck.ok(sticks, "two-tooth, " + br.txt + ": " + std::to_string(br.sticks) + " stick phase(s) per period");
    ck.zero(mu_ref - br.mu, "two-tooth, " + br.txt + ": equals mu(beta, gamma = 1) (Eq. 18's statement for this wave)");
  }
  ck.zero(m1.subs(b == 5) - m2.subs(b == 5), "two-tooth: continuous at beta = 5 (" + ex_to_string(m1.subs(b == 5)) + ")");
  ck.zero(m2.subs(b == 10) - 1, "two-tooth: continuous at beta = 10 (mu = mu0, Eq. 6)");
  for (auto& m : {std::pair<ex, std::string>{m1, "0 < beta < 5"}, {m2, "5 <= beta < 10"}}) {
    ck.nonzero(m.first - 2 * b / (4 + b), "two-tooth (" + m.second + ") = Eq. 19 tri 2 beta/(4 + beta)");
    ck.nonzero(m.first - b / 2, "two-tooth (" + m.second + ") = Eq. 19 str beta/2");
    ck.nonzero(m.first - b / (2 + b), "two-tooth (" + m.second + ") = Eq. 19 stl beta/(2 + beta)");
  }
  // not an asymmetric unit-period triangle in disguise: 13 ((1 - d) beta + 2) = 50 + 5 beta has no solution d
  ck.ok(!expand(13 * ((1 - d) * b + 2) - (50 + 5 * b)).coeff(b, 0).is_zero(),
        "two-tooth (0 < beta < 5) = beta/((1 - d) beta + 2) for no d (constant terms 26 != 50)");
  ck.ok(!m2.subs(b == 0).is_zero(), "two-tooth (5 <= beta < 10) is not of the form beta * (...) of any triangle");

  // =========================================================== (a) asymmetric single triangles
  for (numeric dv : {numeric(1, 3), numeric(1, 5), numeric(2, 3)}) {
    Wave tr = from_points({{0, -1}, {dv, 1}});
    std::string ds = ex_to_string(dv), bc = ex_to_string(2 / dv);
    ex pred = rho_d.subs(d == dv);
    bool all = true, ind = true;
    for (auto& gr : std::vector<GR>{{-1, 1, "-1 < gamma < 1"}, {1, 1, "gamma = 1"}}) {
      Result r = go(tr, Box{"0 < beta < " + bc + ", " + gr.txt, 0, 2 / dv, gr.g0, gr.g1}, "triangle, peak at d = " + ds, gr.g0 == -1);
      all = all && normal(r.mu - pred).is_zero() && r.sticks == 1;
      ind = ind && normal(diff(r.mu, G())).is_zero();
      Result r2 = go(tr, Box{"beta > " + bc + ", " + gr.txt, 2 / dv, -1, gr.g0, gr.g1}, "triangle, peak at d = " + ds, false);
      all = all && normal(r2.mu - 1).is_zero() && r2.sticks == 0;
    }
    ck.ok(all && ind, "asymmetric triangle d = " + ds + ": mu/mu0 = " + ex_to_string(pred) +
                          " for beta < " + bc + ", 1 beyond, on -1 < gamma < 1 and gamma = 1 (engine)");
  }

  // =========================================================== remark: teeth with lower peaks, equal slopes
  {
    std::cout << "== remark: teeth of equal slopes 8, peaks 1 and 0, flat valley (normalised: +3/8)\n";
    Wave rw = from_points({{0, -1}, {numeric(1, 4), 1}, {numeric(1, 2), -1}, {numeric(5, 8), 0}, {numeric(3, 4), -1}}, numeric(3, 8));
    std::cout << "     pieces: " << wave_text(rw) << "\n";
    ck.zero(wave_mean(rw), "remark wave: zero mean (min -5/8, max 11/8, amplitude 1)");
    Result r1 = go(rw, Box{"0 < beta < 8, -11/8 < gamma < -3/8", 0, 8, numeric(-11, 8), numeric(-3, 8)}, "remark wave (one tooth in contact)");
    Result r2 = go(rw, Box{"0 < beta < 8, -3/8 < gamma < 5/8", 0, 8, numeric(-3, 8), numeric(5, 8)}, "remark wave (two teeth)");
    Result r3 = go(rw, Box{"0 < beta < 8, gamma = 5/8", 0, 8, numeric(5, 8), numeric(5, 8)}, "remark wave (no jumping edge)");
    ck.ok(normal(r1.mu - 2 * b / (8 + b)).is_zero() && normal(r2.mu - 2 * b / (8 + b)).is_zero() && normal(r3.mu - 2 * b / (8 + b)).is_zero(),
          "remark wave: mu/mu0 = 2 beta/(8 + beta) on the whole jumping range (the peak-0 tooth is not at the global max)");
  }

  // =========================================================== (a) controls: NOT invariant
  std::cout << "== (a) controls\n";
  {
    Wave trap = samples({-1, 1, 1, -1});  // flat top (and flat bottom), slopes 8, 0, -8, 0
    ck.zero(wave_mean(trap), "trapezoid: zero mean");
    Result r = go(trap, Box{"4 < beta < 8, -1 < gamma < 1", 4, 8, -1, 1}, "trapezoid (flat top)");
    Result r1 = go(trap, Box{"4 < beta < 8, gamma = 1", 4, 8, 1, 1}, "trapezoid (flat top)");
    ck.nonzero(diff(r.mu, G()), "trapezoid (flat top) invariant: d mu/d gamma");
    ck.nonzero(r.mu - r1.mu, "trapezoid (flat top): mu(beta, gamma) = mu(beta, 1)");
  }
  {
    Wave lm = samples({-1, 1, numeric(-1, 2), 1}, numeric(-1, 8));  // local min -5/8 above the global min -9/8
    std::cout << "     local-minimum wave: " << wave_text(lm) << "\n";
    ck.zero(wave_mean(lm), "local-minimum wave (-1, 1, -1/2, 1) - 1/8: zero mean, amplitude 1");
    Result lo = go(lm, Box{"2 < beta < 6, -7/8 < gamma < 5/8", 2, 6, numeric(-7, 8), numeric(5, 8)}, "local minimum (valley in the air)");
    Result hi = go(lm, Box{"2 < beta < 6, 5/8 < gamma < 9/8", 2, 6, numeric(5, 8), numeric(9, 8)}, "local minimum (valley in contact)");
    Result rf = go(lm, Box{"2 < beta < 6, gamma = 9/8", 2, 6, numeric(9, 8), numeric(9, 8)}, "local minimum (no jumping edge)");
    ck.nonzero(diff(hi.mu, G()), "local-minimum wave invariant: d mu/d gamma on 5/8 < gamma < 9/8");
    ck.nonzero(lo.mu - rf.mu, "local-minimum wave: mu(beta, gamma < 5/8) = mu(beta, 9/8) (9/8 = -min w, onset of jumping)");
    ck.zero(diff(lo.mu, G()), "(for the record) local-minimum wave: no gamma-dependence once both valleys are in the air");
  }
  Wave kc = samples({-1, numeric(1, 2), 1, 0}, numeric(-1, 8));  // rising slopes 6 then 2 (concave cap), falling -4
  {
    std::cout << "     kinked wave: " << wave_text(kc) << "\n";
    ck.zero(wave_mean(kc), "kinked wave (-1, 1/2, 1, 0) - 1/8: zero mean, amplitude 1");
    Result lo = go(kc, Box{"0 < beta < 2, -7/8 < gamma < -3/8", 0, 2, numeric(-7, 8), numeric(-3, 8)}, "kink in the rising flank (contact above the kink)");
    Result hi = go(kc, Box{"0 < beta < 2, -3/8 < gamma < 1/8", 0, 2, numeric(-3, 8), numeric(1, 8)}, "kink in the rising flank (contact below the kink)");
    ck.nonzero(diff(hi.mu, G()), "kinked wave invariant: d mu/d gamma on -3/8 < gamma < 1/8");
    ck.nonzero(lo.mu - hi.mu, "kinked wave: same mu above and below the kink");
    ck.zero(lo.mu - normal(rho.subs(lst{a == 2, bs == 4})), "(for the record) above the kink the cap is one linear tooth (2, 4): mu/mu0 = 3 beta/(4 + beta)");
  }

  // =========================================================== (b) convexity
  std::cout << "== (b) convexity: where does stick start?\n";
  {  // concave cap (slope 6 then 2): onset at first contact
    Result r1 = go(kc, Box{"0 < beta < 2, -3/8 < gamma < 1/8", 0, 2, numeric(-3, 8), numeric(1, 8)}, "kinked wave, concave cap", false);
    Result r2 = go(kc, Box{"4 < beta < 6, -3/8 < gamma < 1/8", 4, 6, numeric(-3, 8), numeric(1, 8)}, "kinked wave, concave cap");
    ck.ok(has_first_contact_onset(r1) && r1.sticks == 1 && has_first_contact_onset(r2) && r2.sticks == 1,
          "concave cap (slopes 6 then 2): the only stick onset is at first contact (0 < beta < 2 and 4 < beta < 6)");
  }
  {  // convex rising flank (slope 2 then 6), first contact below the kink: onset at the kink
    Wave kv = samples({-1, numeric(-1, 2), 1, 0}, numeric(1, 8));
    std::cout << "     convex-flank wave: " << wave_text(kv) << "\n";
    ck.zero(wave_mean(kv), "convex-flank wave (-1, -1/2, 1, 0) + 1/8: zero mean, amplitude 1");
    Box bx{"2 < beta < 6, 3/8 < gamma < 7/8", 2, 6, numeric(3, 8), numeric(7, 8)};
    Result r = go(kv, bx, "convex flank, first contact below the kink");
    bool at_kink = r.sticks == 1 && !has_first_contact_onset(r);
    for (auto& e : r.events) if (e.kind.find("onset") != std::string::npos) at_kink = at_kink && normal(e.at - numeric(1, 4)).is_zero();
    ck.ok(at_kink, "convex flank, 2 < beta < 6, 3/8 < gamma < 7/8: stick starts at the kink phi = 1/4 (inside the contact), not at first contact");
    // a ramp from first contact would exceed n: n - ramp at the kink < 0 (s <= n violated)
    ex pc = (numeric(7, 8) - g) / 2;  // first contact: -7/8 + 2 phi + gamma = 0
    ex nk = g - numeric(3, 8), rk = b * (numeric(1, 4) - pc);
    ck.ok(decide(nk - rk, box_regime(bx), "n - first-contact ramp at the kink") < 0,
          "wrong variant rejected: stick from first contact (its ramp exceeds n at the kink: s <= n violated; proved sign)");
    Result r2 = go(kv, Box{"4 < beta < 6, -1/8 < gamma < 3/8", 4, 6, numeric(-1, 8), numeric(3, 8)}, "convex flank, first contact above the kink", false);
    ck.ok(has_first_contact_onset(r2) && r2.sticks == 1, "convex flank, first contact above the kink (cap linear): onset at first contact");
  }
  // ---- the sine: gamma = 1/2, beta = 6 (counterexample) and gamma = -1/2 (concave cap)
  Digits = 50;
  const numeric tol = numeric(1) / numeric(10).power(40);
  {
    std::cout << "-- sine, gamma = 1/2, beta = 6 (first contact below the inflection point)\n";
    const ex gm = numeric(1, 2), be = 6, P = PHI();
    const ex w = sin(2 * Pi * P), wp = 2 * Pi * cos(2 * Pi * P);
    const ex W = -cos(2 * Pi * P) / (2 * Pi);  // antiderivative of w
    ck.zero(diff(W, PHI()) - w, "antiderivative of sin(2 pi phi) is -cos(2 pi phi)/(2 pi)");
    const ex p0 = numeric(-1, 12), pe = numeric(7, 12);  // contact (-1/12, 7/12): sin = -1/2 at both ends
    ck.zero(gm + w.subs(P == p0), "first contact phi0 = -1/12: gamma + sin(2 pi phi0) = 0");
    ck.zero(gm + w.subs(P == pe), "contact end 7/12");
    const ex slope0 = wp.subs(P == p0);
    std::cout << "     n'(phi0+) = " << slope0 << " = " << num(slope0) << ",  max w' = 2 pi = " << num(2 * Pi) << "\n";
    ck.zero(slope0 - Pi * sqrt(ex(3)), "first-contact slope = pi sqrt3 = 2 pi sqrt(1 - gamma^2)");
    ck.ok(num(be - slope0).is_positive() && num(2 * Pi - be).is_positive(), "pi sqrt3 (5.441) < beta = 6 < 2 pi (6.283)");
    // interior onset: w'(phi1) = beta on the rising part where w' increases (-1/4 < phi < 0)
    const ex th = acos(be / (2 * Pi)), p1 = -th / (2 * Pi);
    ck.zero(2 * Pi * cos(th) - be, "phi1 = -acos(beta/(2 pi))/(2 pi): w'(phi1) = 2 pi cos(acos(3/pi)) = 6 (cos even)");
    ck.ok(abs(num(wp.subs(P == p1) - be)) < tol,
          "w'(phi1) - beta = 0 numerically (< 1e-40)");
    ck.ok(num(p1 - p0).is_positive() && num(-p1).is_positive(), "phi0 = -1/12 < phi1 = " + ex_to_string(num(p1)) + " < 0 (inflection point)");
    // before phi1 (phi0 < phi < phi1): n' = w' increasing up to beta, so n' < beta: slip, s = n
    // the first-contact ramp would exceed n already at phi1:
    std::cout << "     at phi1: n = " << num(gm + w.subs(P == p1)) << ", first-contact ramp 6 (phi1 - phi0) = " << num(be * (p1 - p0)) << "\n";
    ck.ok(num(be * (p1 - p0) - (gm + w.subs(P == p1))).is_positive(),
          "wrong variant rejected: stick from first contact (ramp 6 (phi - phi0) exceeds n at phi1: s <= n violated)");
    // stick end, Eq. 8: g(phi) = w - w1 - beta (phi - phi1) is concave on (0, 1/2), g(0) > 0 > g(1/4)
    const ex w1 = w.subs(P == p1), gfun = w - w1 - be * (P - p1);
    ck.ok(num(gfun.subs(P == 0)).is_positive() && num(gfun.subs(P == numeric(1, 4))).is_negative(),
          "Eq. 8: g(0) > 0 > g(1/4), g concave on (0, 1/2): a unique stick end phi2 in (0, 1/4)");
    const ex p2 = num(bisect(gfun, 0, numeric(1, 4)));
    std::cout << "     phi0 = " << num(p0) << ", phi1 = " << num(p1) << ", phi2 = " << p2 << "\n";
    ck.ok(abs(num(gfun.subs(P == p2))) < tol,
          "phi2 solves Eq. 8 (residual < 1e-40)");
    const ex In = gm * (pe - p0) + W.subs(P == pe) - W.subs(P == p0);
    ck.zero(In - (numeric(1, 3) + sqrt(ex(3)) / (2 * Pi)), "int n = 1/3 + sqrt3/(2 pi)");
    const ex Red = W.subs(P == p2) - W.subs(P == p1) - w1 * (p2 - p1) - be * pow(p2 - p1, 2) / 2;  // Eq. 12 on the stick
    const numeric mu = num(1 - Red / In);
    std::cout << "     int n = " << num(In) << ",  int (n - s) = " << num(Red) << ",  mu/mu0 = " << mu << "\n";
    ck.ok(num(Red).is_positive() && (1 - mu).is_positive(), "sine, gamma = 1/2, beta = 6: friction is reduced (mu < mu0) although beta > first-contact slope");
    // independent check of s: the envelope min over tau of n(phi - tau) + beta tau (model.md), candidates:
    // tau = 0, the contact points, and the stationary points w'(psi) = beta (psi = -+ acos(beta/2pi)/2pi mod 1)
    auto nval = [&](const ex& ph) { numeric v = num(gm + w.subs(P == ph)); return v.is_positive() ? v : numeric(0); };
    auto envelope = [&](const numeric& ph) {
      numeric best = nval(ph);
      std::vector<ex> cand = {p0, pe, p1, -p1};
      for (auto& c : cand) {
        numeric cv = num(c);
        while (cv > ph) cv -= 1;
        while (cv <= ph - 1) cv += 1;
        numeric v = nval(cv) + num(be) * (ph - cv);
        if (v < best) best = v;
      }
      return best;
    };
    auto s_constructed = [&](const numeric& ph) {
      if (ph > num(p1) && ph < num(p2)) return num(gm + w1 + be * (ph - p1));
      return nval(ph);
    };
    numeric worst = 0;
    int count = 0;
    for (int k = -29; k < 31; ++k) {  // phases -29/60 ... 30/60, plus the event neighbourhoods
      numeric ph(k, 60);
      worst = std::max(worst, abs(envelope(ph) - s_constructed(ph)));
      ++count;
    }
    for (auto& ph : {num(p0) + numeric(1, 1000), num(p1) - numeric(1, 1000), num(p1) + numeric(1, 1000), ex_to<numeric>(p2) - numeric(1, 1000),
                     ex_to<numeric>(p2) + numeric(1, 1000)}) {
      worst = std::max(worst, abs(envelope(ph) - s_constructed(ph)));
      ++count;
    }
    ck.ok(worst < tol,
          "s of this construction = lower envelope min_tau [n(phi - tau) + beta tau] at " + std::to_string(count) + " phases (max diff " +
              ex_to_string(worst) + ")");
    ck.ok((num(gm + w.subs(P == num(p0) + numeric(1, 1000))) - envelope(num(p0) + numeric(1, 1000))).is_zero(),
          "just after first contact s = n (slip): no stick at first contact");
  }
  {
    std::cout << "-- sine, gamma = -1/2 (first contact above the inflection point: concave cap)\n";
    const ex gm = numeric(-1, 2), P = PHI();
    const ex w = sin(2 * Pi * P), wp = 2 * Pi * cos(2 * Pi * P);
    const ex p0 = numeric(1, 12);
    ck.zero(gm + w.subs(P == p0), "first contact phi0 = 1/12");
    ck.zero(wp.subs(P == p0) - Pi * sqrt(ex(3)), "first-contact slope pi sqrt3 = beta_c(-1/2) (largest slope of the clipped n)");
    // beta = 4 < pi sqrt3: ramp 4 (phi - 1/12) from first contact, Eq. 8 on the falling side
    // g = n - ramp: g(phi0) = 0, g'(phi0) = pi sqrt3 - 4 > 0, g concave on the contact (sin > 0), largest
    // where w' = 4 (phi_m = acos(2/pi)/(2 pi)); it returns to 0 once, before the peak 1/4
    const ex be = 4, gfun = gm + w - be * (P - p0), pm = acos(be / (2 * Pi)) / (2 * Pi);
    ck.ok(num(Pi * sqrt(ex(3)) - be).is_positive() && num(gfun.subs(P == pm)).is_positive() && num(gfun.subs(P == numeric(1, 4))).is_negative(),
          "beta = 4 < pi sqrt3: the first-contact ramp starts below n (g'(phi0) > 0, g(phi_m) > 0) and meets it before the peak (g(1/4) < 0)");
    const ex p2 = num(bisect(gfun, num(pm), numeric(1, 4)));
    std::cout << "     stick from phi0 = 1/12 to phi2 = " << p2 << "\n";
    // envelope at phases inside the stick equals the ramp from first contact
    numeric worst = 0;
    for (int k = 1; k < 20; ++k) {
      numeric ph = num(p0 + (p2 - p0) * numeric(k, 20));
      numeric ramp = num(be * (ph - p0));
      // envelope candidates: tau = 0, contact points, stationary points w' = 4
      numeric best = num(gm + w.subs(P == ph));
      ex t4 = acos(be / (2 * Pi)) / (2 * Pi);
      for (auto& c : std::vector<ex>{p0, numeric(5, 12) - 1, t4, -t4, t4 - 1, -t4 - 1}) {
        numeric cv = num(c);
        if (cv > ph || cv <= ph - 1) continue;
        numeric nv = num(gm + w.subs(P == cv));
        if (nv.is_negative()) nv = 0;
        numeric v = nv + num(be) * (ph - cv);
        if (v < best) best = v;
      }
      worst = std::max(worst, abs(best - ramp));
    }
    ck.ok(worst < tol,
          "beta = 4: s = 4 (phi - phi0) on the stick (envelope, 19 phases): stick starts at first contact");
  }

  // ------------------------------------------------------------------ summary of branch conditions
  std::cout << "branch conditions decided: " << boxlog().engine_proved + boxlog().box_proved + boxlog().sampled.size() << " in box regimes ("
            << boxlog().engine_proved << " proved by the engine via affine factors, " << boxlog().box_proved
            << " proved here as multilinear factors on the box, " << boxlog().sampled.size() << " checked at 60 exact sample points only)\n";
  for (auto& s : boxlog().sampled) std::cout << "   sampled only: " << s << "\n";
  {  // sign decisions made directly in main (not inside an engine run)
    boxlog().seen.resize(condition_log().size(), false);
    size_t others = 0, oproved = 0;
    for (size_t i = 0; i < condition_log().size(); ++i)
      if (!boxlog().seen[i]) { ++others; if (condition_log()[i].proved) ++oproved; }
    std::cout << "further sign decisions: " << others << " (" << oproved << " proved via affine factors)\n";
    if (oproved != others) { std::cout << "   some were only sampled\n"; ck.ok(false, "all further sign decisions proved"); }
  }
  return ck.finish("proof.sec3_uniqueness_convexity");
}
