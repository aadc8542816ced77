// Symbolic stick-slip construction for piecewise-linear periodic normal forces (GiNaC).
// Used only by the programs in proofs/. Nothing here knows any of the paper's results:
// the waves are the definitions of Eq. 16 / the catalogue, everything else is derived.
#pragma once
#include <ginac/ginac.h>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace proofs {
using namespace GiNaC;

inline const symbol& B() { static symbol s("beta"); return s; }
inline const symbol& G() { static symbol s("gamma"); return s; }
inline const symbol& PHI() { static symbol s("phi"); return s; }
inline std::string ex_to_string(const ex& e) { std::ostringstream os; os << e; return os.str(); }

// n(phi) = a + m (phi - x0) on [x0, x1); value at x1 is the left limit.
struct Seg { ex x0, x1, a, m; };
using Wave = std::vector<Seg>;

// The catalogue waves (model.md / paper Eq. 16), unit period.
inline Wave wave(const std::string& name) {
  if (name == "tri") return {{0, numeric(1, 2), -1, 4}, {numeric(1, 2), 1, 1, -4}};
  if (name == "str") return {{0, 1, -1, 2}};
  if (name == "stl") return {{0, 1, 1, -2}};
  if (name == "sqr") return {{0, numeric(1, 2), 1, 0}, {numeric(1, 2), 1, -1, 0}};
  if (name == "tri2")  // triangle of half period: two minima per period (not in the paper)
    return {{0, numeric(1, 4), -1, 8}, {numeric(1, 4), numeric(1, 2), 1, -8},
            {numeric(1, 2), numeric(3, 4), -1, 8}, {numeric(3, 4), 1, 1, -8}};
  throw std::invalid_argument("unknown wave " + name);
}

// A regime: open convex polygon in the (beta, gamma) plane given by the vertices and
// recession rays of its closure (possibly degenerate, e.g. gamma = 1 fixed), plus its
// description as inequalities. Sample points are exact rationals strictly inside.
struct Regime {
  std::string text;
  std::vector<std::pair<numeric, numeric>> verts, rays;
  std::vector<exmap> samples;
};

inline Regime make_regime(std::string text, std::vector<std::pair<numeric, numeric>> verts,
                          std::vector<std::pair<numeric, numeric>> rays = {}) {
  Regime r{std::move(text), std::move(verts), std::move(rays), {}};
  unsigned long long state = 12345;
  auto rnd = [&](int lo, int hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + int((state >> 33) % (unsigned long long)(hi - lo + 1));
  };
  const int K = 60;
  for (int k = 0; k < K; ++k) {
    std::vector<numeric> w;
    numeric sum = 0;
    for (size_t i = 0; i < r.verts.size(); ++i) {
      // mix of very unbalanced and balanced weights, to probe near edges/vertices
      numeric wi = (k % 3 == 0) ? numeric(rnd(1, 1000)) : numeric(rnd(1, 9));
      if (k % 5 == 1 && i == size_t(k) % r.verts.size()) wi = wi * 10000;
      w.push_back(wi);
      sum += wi;
    }
    numeric b = 0, g = 0;
    for (size_t i = 0; i < r.verts.size(); ++i) {
      b += w[i] / sum * r.verts[i].first;
      g += w[i] / sum * r.verts[i].second;
    }
    for (auto& ray : r.rays) {
      numeric c = (k % 4 == 0) ? numeric(rnd(1, 1000)) : numeric(rnd(1, 100), 37);
      b += c * ray.first;
      g += c * ray.second;
    }
    exmap m;
    m[B()] = b;
    m[G()] = g;
    r.samples.push_back(m);
  }
  return r;
}

struct Condition { std::string what; ex e; int sign; bool proved; };
inline std::vector<Condition>& condition_log() { static std::vector<Condition> v; return v; }

inline int sgn(const numeric& x) { return x.is_zero() ? 0 : (x.is_positive() ? 1 : -1); }

// Sign of a factor that is affine in (beta, gamma) on the relative interior of the regime:
// an affine f that is >= 0 at every vertex and non-decreasing along every ray is >= 0 on the
// closure, and > 0 on the relative interior unless it vanishes identically there.
inline bool linear_factor_sign(const ex& f, const Regime& R, int& out) {
  ex fe = expand(f);
  if (!fe.is_polynomial(lst{B(), G()})) return false;
  if (fe.degree(B()) > 1 || fe.degree(G()) > 1) return false;
  if (!fe.coeff(B(), 1).coeff(G(), 1).is_zero()) return false;
  bool pos = true, neg = true, allzero = true;
  ex base;
  for (auto& v : R.verts) {
    ex val = fe.subs(lst{B() == v.first, G() == v.second});
    if (!is_a<numeric>(val)) return false;
    int s = sgn(ex_to<numeric>(val));
    if (s < 0) pos = false;
    if (s > 0) neg = false;
    if (s != 0) allzero = false;
    base = v.first;
  }
  for (auto& r : R.rays) {
    auto& v = R.verts.front();
    ex d = fe.subs(lst{B() == v.first + r.first, G() == v.second + r.second}) -
           fe.subs(lst{B() == v.first, G() == v.second});
    if (!is_a<numeric>(d)) return false;
    int s = sgn(ex_to<numeric>(d));
    if (s < 0) pos = false;
    if (s > 0) neg = false;
    if (s != 0) allzero = false;
  }
  if (allzero) { out = 0; return true; }
  if (pos) { out = 1; return true; }
  if (neg) { out = -1; return true; }
  return false;
}

// The sign of p from its factorisation: numeric factors by value, every other factor (or the base
// of a positive integer power) by factor_sign(base, fs); false if one cannot be decided.
template <class FactorSign>
bool sign_by_factors(const ex& p, FactorSign factor_sign, int& out) {
  ex f = factor(p);
  std::vector<ex> ops;
  if (is_a<mul>(f)) for (size_t i = 0; i < f.nops(); ++i) ops.push_back(f.op(i));
  else ops.push_back(f);
  int s = 1;
  for (auto& o : ops) {
    if (is_a<numeric>(o)) { s *= sgn(ex_to<numeric>(o)); continue; }
    ex base = o; long e = 1;
    if (is_a<power>(o) && is_a<numeric>(o.op(1)) && ex_to<numeric>(o.op(1)).is_pos_integer()) {
      base = o.op(0); e = ex_to<numeric>(o.op(1)).to_long();
    }
    int fs;
    if (!factor_sign(base, fs)) return false;
    if (fs == 0) { out = 0; return true; }
    if (e % 2 == 1) s *= fs;
  }
  out = s;
  return true;
}

inline bool factored_sign(const ex& p, const Regime& R, int& out) {
  return sign_by_factors(p, [&](const ex& base, int& fs) { return linear_factor_sign(base, R, fs); }, out);
}

// Decide the sign of e on the regime. Exact if e normalises to a number; otherwise the sign
// must be the same at every sample point (else the regime is not uniform: throw), and a proof
// via linear factors is attempted. Every decision is logged.
inline int decide(const ex& e0, const Regime& R, const std::string& what) {
  ex e = normal(e0);
  if (is_a<numeric>(e)) return sgn(ex_to<numeric>(e));
  int s = 2;
  for (auto& m : R.samples) {
    ex v = normal(e.subs(m));
    if (!is_a<numeric>(v)) throw std::runtime_error("non-numeric value of " + what);
    int sv = sgn(ex_to<numeric>(v));
    if (s == 2) s = sv;
    else if (s != sv || sv == 0) {
      std::ostringstream os;
      os << "regime [" << R.text << "] is not uniform: sign of " << what << " = " << e
         << " changes between sample points";
      throw std::runtime_error(os.str());
    }
  }
  if (s == 0) throw std::runtime_error("condition vanishes at samples but not identically: " + what);
  int sn, sd;
  bool proved = factored_sign(numer(e), R, sn) && factored_sign(denom(e), R, sd);
  if (proved && sn * sd != s)
    throw std::runtime_error("internal: proved sign disagrees with samples for " + what);
  condition_log().push_back({what, e, s, proved});
  return s;
}

struct Event { std::string kind; ex at; };
struct Result {
  ex In;      // integral of n over one period
  ex Red;     // integral of (n - s) over one period (= Psi without jumping)
  ex Is;      // integral of s
  ex mu;      // Is / In
  std::vector<Event> events;
  int sticks = 0;
};

// n = max(gamma + w, 0), segment by segment; contact points solve linear equations.
inline Wave clip(const Wave& w, const ex& g, const Regime& R) {
  Wave n;
  for (size_t i = 0; i < w.size(); ++i) {
    const Seg& s = w[i];
    ex v0 = g + s.a, v1 = g + s.a + s.m * (s.x1 - s.x0);
    std::string id = "seg" + std::to_string(i);
    int s0 = decide(v0, R, "gamma+w at start of " + id), s1 = decide(v1, R, "gamma+w at end of " + id);
    if (s0 >= 0 && s1 >= 0) { n.push_back({s.x0, s.x1, v0, s.m}); continue; }
    if (s0 <= 0 && s1 <= 0) { n.push_back({s.x0, s.x1, 0, 0}); continue; }
    ex xc = lsolve(v0 + s.m * (PHI() - s.x0) == 0, PHI());
    if (s0 > 0) { n.push_back({s.x0, xc, v0, s.m}); n.push_back({xc, s.x1, 0, 0}); }
    else        { n.push_back({s.x0, xc, 0, 0});   n.push_back({xc, s.x1, 0, s.m}); }
  }
  return n;
}

inline ex integrate(const ex& f, const ex& lo, const ex& hi) {
  return normal(integral(PHI(), lo, hi, f).eval_integ());
}

// Forward dynamics over one period from a phase where n attains its infimum (there s = n,
// because s <= n and s >= inf n), with the event logic of the model:
//  slip: s = n; stick starts at an upward jump of n or where n' > beta;
//  stick: s = s_a + beta (phi - phi_a) until n meets the ramp (linear equation) or jumps below it.
inline Result run(const Wave& n, const ex& beta, const Regime& R) {
  Result res;
  const size_t N = n.size();
  res.In = 0;
  for (auto& s : n) res.In += integrate(s.a + s.m * (PHI() - s.x0), s.x0, s.x1);
  res.In = normal(res.In);
  // infimum: candidates are right limits at x0 and left limits at x1
  ex best = n[0].a; size_t start = 0;
  for (size_t j = 0; j < N; ++j) {
    ex c0 = n[j].a, c1 = n[j].a + n[j].m * (n[j].x1 - n[j].x0);
    if (decide(c0 - best, R, "min search (start of seg)") < 0) { best = c0; start = j; }
    if (decide(c1 - best, R, "min search (end of seg)") < 0) { best = c1; start = (j + 1) % N; }
  }
  const ex s_start = best;
  ex s_in = best;
  bool stick = false;
  ex sa, pa;
  res.Red = 0;
  for (size_t t = 0; t <= N; ++t) {
    size_t j = (start + t) % N;
    ex shift = (start + t >= N) ? ex(1) : ex(0);
    const Seg& s = n[j];
    ex X0 = s.x0 + shift, X1 = s.x1 + shift, A = s.a, M = s.m, L = s.x1 - s.x0;
    int sd = decide(A - s_in, R, "n(x0+) - s(x0-) at phase " + ex_to_string(X0));
    if (t == N) {  // back at the start point: closure
      ex s_final = (sd < 0) ? A : s_in;
      if (!normal(s_final - s_start).is_zero()) throw std::runtime_error("steady state does not close");
      if (stick && sd < 0) res.events.push_back({"stick end (downward jump)", X0});
      break;
    }
    if (stick && sd < 0) { stick = false; res.events.push_back({"stick end (downward jump)", X0}); }
    if (!stick && sd > 0) {
      stick = true; sa = s_in; pa = X0; ++res.sticks;
      res.events.push_back({"stick onset (upward jump)", X0});
    }
    if (!stick) {
      if (decide(M - beta, R, "slope - beta at phase " + ex_to_string(X0)) > 0) {
        stick = true; sa = A; pa = X0; ++res.sticks;
        res.events.push_back({normal(A).is_zero() && t > 0 ? "stick onset (first contact, n' > beta)"
                                                             : "stick onset (n' > beta)", X0});
      } else {
        s_in = A + M * L;
        continue;
      }
    }
    ex ramp = sa + beta * (PHI() - pa);
    ex g = A + M * (PHI() - X0) - ramp;  // n - ramp, >= 0 while sticking
    ex g1 = normal(g.subs(PHI() == X1));
    if (decide(g1, R, "n - ramp at end of seg, phase " + ex_to_string(X1)) > 0) {
      res.Red += integrate(g, X0, X1);
      s_in = normal(ramp.subs(PHI() == X1));
      continue;
    }
    ex xc = normal(lsolve(g == 0, PHI()));
    res.Red += integrate(g, X0, xc);
    res.events.push_back({"stick end (n meets ramp, Eq. 8)", xc});
    stick = false;
    s_in = A + M * L;
  }
  res.Red = normal(res.Red);
  res.Is = normal(res.In - res.Red);
  res.mu = normal(res.Is / res.In);
  return res;
}

// ---------------------------------------------------------------- reporting
struct Checker {
  int fails = 0, passes = 0;
  void ok(bool c, const std::string& what) {
    std::cout << (c ? "  [ok]   " : "  [FAIL] ") << what << "\n";
    c ? ++passes : ++fails;
  }
  void zero(const ex& d, const std::string& what) {
    ex z = normal(d);
    ok(z.is_zero(), what + "   (difference normalises to " + ex_to_string(z) + ")");
  }
  void nonzero(const ex& d, const std::string& what) {
    ex z = normal(d);
    ok(!z.is_zero(), "wrong variant rejected: " + what + "   (difference = " + ex_to_string(z) + ")");
  }
  void throws(const std::function<void()>& f, const std::string& what) {
    try { f(); ok(false, "wrong variant rejected: " + what + " (machinery did NOT refuse)"); }
    catch (std::exception& e) { ok(true, "wrong variant rejected: " + what + " -- " + e.what()); }
  }
  int finish(const std::string& name) {
    std::cout << name << ": " << passes << " checks passed, " << fails << " failed\n";
    return fails ? 1 : 0;
  }
};

inline void print_run(const std::string& title, const Result& r, const Regime& R) {
  std::cout << "-- " << title << "   regime: " << R.text << "\n";
  for (auto& e : r.events) std::cout << "     event: " << e.kind << " at phi = " << e.at << "\n";
  std::cout << "     int n = " << r.In << ",  int (n - s) = " << r.Red << ",  mu/mu0 = " << r.mu << "\n";
}

inline void print_conditions() {
  int proved = 0, sampled = 0;
  for (auto& c : condition_log()) (c.proved ? proved : sampled)++;
  std::cout << "branch conditions decided: " << condition_log().size() << " (" << proved
            << " proved on the regime polygon via linear factors, " << sampled
            << " checked at 60 exact sample points only)\n";
  for (auto& c : condition_log())
    if (!c.proved) std::cout << "   sampled only: " << c.what << ": " << c.e << (c.sign > 0 ? " > 0" : " < 0") << "\n";
}

}  // namespace proofs
