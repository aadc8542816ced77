// Binds vibrofric.mu and vibrofric.psi (broadcasting over beta and gamma, broadcast.hpp) and
// vibrofric.rig (rig dynamics at one point).
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "broadcast.hpp"
#include "common.hpp"
#include "vibrofric/api/limits.hpp"
#include "vibrofric/api/rig.hpp"

namespace vibrofric::python {

namespace {

unsigned to_threads(const py::object& x) {
  const auto t = optional_int(x, "threads");
  if (!t) return 0;
  if (*t < 0 || *t > static_cast<long long>(max_threads))
    throw InputError("threads = " + std::to_string(*t) + ": expected 0 (all cores) to " + std::to_string(max_threads));
  return static_cast<unsigned>(*t);
}

constexpr const char* mu_doc = R"doc(mu(wave, beta, gamma, *, profile="flat", digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False, nan_on_error=False, certify=False, kappa=None, omega=None, zeta=None, longitudinal=None, transverse=None, phase=None, in_plane_wave=None)

The macroscopic coefficient of friction mu/mu0 = int s dphi / int n dphi (Eq. 15; Eqs. 9, 13 of
the paper) for sliding velocity beta (Eq. 5) and mean indentation gamma = u/A (Eq. 14), in the
periodic steady state; curved indenters (profile) by the method of dimensionality reduction.

wave      a name -- 'sine' (harmonic), 'triangle', 'sawtooth-right', 'sawtooth-left', 'square',
          'power:P', 'samples:FILE', 'fourier:FILE' -- or a Wave from wave(), samples(), fourier()
          or fit().
beta      > 0; gamma: contact requires gamma + max w > 0 (gamma > -1 for the catalogue waves).
          Scalars, arrays or nested sequences; they broadcast like numpy ufunc arguments.
          Floats mean the shortest decimal text of their float64 value (0.1 is the decimal 0.1,
          as on the tool's command line; a numpy.float32 is widened to float64 first, so
          float32(1.1) is 1.100000023841858); decimal strings are exact at any precision.
profile   'flat' (the paper's punch), 'sphere', 'cone', 'power:N', 'wearflat:LAMBDA',
          'profile:FILE', or a Profile from profile().
type      None/'double' (float64 ndarray, correctly rounded: the nearest double of the exact
          value, as the tool's --type double), 'long-double' (numpy.longdouble),
          'cpp_bin_float_50', 'cpp_bin_float_100', 'mpfr'.
digits    D significant digits (mpfr): values correct to D digits as decimal strings, or as
          mpmath.mpf (created at D + 3 digits) when mpmath is importable.
threads   worker threads for the batch; 0: all cores. The GIL is released while it runs.
max_iterations  root-finder budget per event (default 200 + working bits).
escalate  double and fixed types: recompute in mpfr where the type's rounding is not enough.
strings   return the library's decimal strings for every type.
kappa, omega, zeta  rig dynamics (the tool's --kappa, --omega, --zeta; model.md): a body of mass m
          on a system spring k_s with damping c instead of the paper's quasi-static spring;
          kappa = k_s/k_x > 0, omega = sqrt(k_x/m)/(2 pi f) > 0, zeta = c/(2 sqrt(m k_s)) >= 0
          (default 0). Scalars (decimal strings or floats); flat punch; sine, Fourier and
          piecewise-linear waves.
longitudinal, transverse, phase, in_plane_wave  in-plane oscillation along and across the sliding
          direction (the tool's --longitudinal, --transverse, --phase, --in-plane-wave; model.md):
          the spring's far end moves as (beta phi + a_l p(phi + P), a_t p(phi + P)), a_l =
          longitudinal >= 0, a_t = transverse >= 0, P = phase in periods (default 0), p a
          catalogue wave (default 'sine'). wave='constant' with gamma=None: a constant normal
          force (a in units of mu0 F_N/k_x). Scalars; beta >= 0 and gamma broadcast. Flat punch.
          A negative value means the oscillation pushes the body forward.

Scalar arguments give a scalar. Raises ValueError (bad input, gamma without contact, beta <= 0)
and vibrofric.SolverError (the solver did not converge), for an array the first failing
element's with its index ('at index (2,): ...'); never returns NaN for a failure, unless
nan_on_error=True (scipy's convention): then a failing element is NaN (None in object arrays)
and the others answer.

certify=True (every wave on the flat punch: the sine, 'power:P', Fourier series, and the
piecewise-linear 'triangle', 'sawtooth-right', 'sawtooth-left', 'square', 'power:1' and samples):
returns (lo, hi) as fractions.Fraction (arrays of them for array arguments), an enclosure of the
exact value narrowed until it proves that the value computed at type/digits is its correct
rounding (a value that is not raises vibrofric.SolverError). For the piecewise-linear waves
lo == hi, the exact rational, and float(lo) is the correctly rounded double; for the others
lo < hi are the ends of an interval computation. Curved profiles raise ValueError. With
longitudinal= (piecewise-linear waves, or wave='constant'), the in-plane drive's exact value.
With kappa and omega (one rig; the sine, Fourier series and piecewise-linear waves), the rig's
periodic state proven to exist (Krawczyk) and mu enclosed on it (vibrofric.rig(certify=True)
gives the whole certificate).
)doc";

}  // namespace

void bind_values(py::module_& m) {
  static constexpr const char* psi_doc = R"doc(psi(wave, beta, *, digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False, nan_on_error=False, certify=False)

The reduction function Psi_w(beta) = int (n - s) dphi without jumping (Eq. 12), which does not
depend on gamma, so that mu/mu0 = 1 - Psi_w(beta)/gamma for gamma >= 1 (Eq. 13). For the
triangle Psi = (4 - beta)/(4 + beta) (Eq. 17). Arguments and results as mu() (certify=True
too); beta broadcasts.
Flat punch only (Psi does not exist for curved profiles).
)doc";
  m.def(
      "mu",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& profile,
         const py::object& digits, const py::object& type, const py::object& threads, const py::object& max_iterations,
         bool escalate, bool strings, bool nan_on_error, bool certify, const py::object& kappa,
         const py::object& omega, const py::object& zeta, const py::object& longitudinal,
         const py::object& transverse, const py::object& phase, const py::object& in_plane_wave) {
        Evaluation e;
        e.quantity = Quantity::mu;
        const bool constant = py::isinstance<py::str>(wave) && wave.cast<std::string>() == "constant";
        const bool amplitude = !longitudinal.is_none() || !transverse.is_none();
        if (constant || amplitude || !phase.is_none() || !in_plane_wave.is_none()) {
          if (!amplitude && (!phase.is_none() || !in_plane_wave.is_none()))
            throw InputError(std::string(phase.is_none() ? "in_plane_wave" : "phase") +
                             " without longitudinal or transverse: give the in-plane amplitude");
          if (!kappa.is_none() || !omega.is_none())
            throw InputError("kappa/omega with an in-plane oscillation: rig dynamics with an in-plane drive is not modelled");
          if (!escalate) throw InputError("escalate=False: in-plane oscillation is always computed in mpfr at two precisions");
          e.inplane = inplane_spec(constant, longitudinal, transverse, phase, in_plane_wave);
        }
        if (!kappa.is_none() || !omega.is_none() || !zeta.is_none()) {
          if (kappa.is_none() || omega.is_none())
            throw InputError(std::string("missing ") + (kappa.is_none() ? "kappa" : "omega") +
                             ": rig dynamics needs kappa and omega (zeta is optional)");
          if (!escalate) throw InputError("escalate=False: rig dynamics is always computed in mpfr at two precisions");
          const auto array = [](const py::object& x) {
            return !x.is_none() && !py::isinstance<py::str>(x) && py::module_::import("numpy").attr("ndim")(x).cast<int>() > 0;
          };
          if (array(kappa) || array(omega) || array(zeta)) {
            if (certify)
              throw InputError("certify=True with an array of kappa, omega or zeta: a proven rig state is given for one rig "
                               "at a time (beta and gamma may be arrays)");
            e.rig_arrays = std::array<py::object, 3>{kappa, omega, zeta};
          } else {
            e.rig.emplace();
            e.rig->kappa = scalar_value(kappa, "kappa");
            e.rig->omega = scalar_value(omega, "omega");
            if (!zeta.is_none()) e.rig->zeta = scalar_value(zeta, "zeta");
            check_rig(*e.rig);
          }
        }
        e.nan_on_error = nan_on_error;
        e.certify = certify;
        e.digits = optional_int(digits, "digits");
        e.type = type;
        e.profile = to_profile(profile);
        e.profile_text = py_repr(profile);
        if (e.inplane && e.inplane->constant_normal && e.profile.kind != ProfileKind::flat)
          throw InputError("wave = 'constant' with profile = " + e.profile_text +
                           ": a curved contact is solved with the normal oscillation (give wave and gamma)");
        e.threads = to_threads(threads);
        if (auto mi = optional_int(max_iterations, "max_iterations")) e.max_iterations = *mi;
        e.escalate = escalate;
        e.strings = strings;
        return evaluate_broadcast(wave, beta, gamma, e);
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "profile"_a = "flat", "digits"_a = py::none(),
      "type"_a = py::none(), "threads"_a = 0, "max_iterations"_a = py::none(), "escalate"_a = true,
      "strings"_a = false, "nan_on_error"_a = false, "certify"_a = false, "kappa"_a = py::none(),
      "omega"_a = py::none(), "zeta"_a = py::none(), "longitudinal"_a = py::none(), "transverse"_a = py::none(),
      "phase"_a = py::none(), "in_plane_wave"_a = py::none(), mu_doc);

  m.def(
      "psi",
      [](const py::object& wave, const py::object& beta, const py::object& digits, const py::object& type,
         const py::object& threads, const py::object& max_iterations, bool escalate, bool strings, bool nan_on_error,
         bool certify) {
        Evaluation e;
        e.quantity = Quantity::psi;
        e.nan_on_error = nan_on_error;
        e.certify = certify;
        e.digits = optional_int(digits, "digits");
        e.type = type;
        e.threads = to_threads(threads);
        if (auto mi = optional_int(max_iterations, "max_iterations")) e.max_iterations = *mi;
        e.escalate = escalate;
        e.strings = strings;
        return evaluate_broadcast(wave, beta, py::none(), e);
      },
      "wave"_a, "beta"_a, py::kw_only(), "digits"_a = py::none(), "type"_a = py::none(), "threads"_a = 0,
      "max_iterations"_a = py::none(), "escalate"_a = true, "strings"_a = false, "nan_on_error"_a = false,
      "certify"_a = false, psi_doc);

  m.def(
      "rig",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& kappa,
         const py::object& omega, const py::object& zeta, const py::object& digits, const py::object& type, bool strings,
         const py::object& profile, bool certify) {
        const WaveSpec w = to_wave(wave);
        const ProfileSpec shape = to_profile(profile);
        const Precision precision = to_precision(optional_int(digits, "digits"), type);
        RigSpec spec;
        spec.kappa = scalar_value(kappa, "kappa");
        spec.omega = scalar_value(omega, "omega");
        if (!zeta.is_none()) spec.zeta = scalar_value(zeta, "zeta");
        const Point point{scalar_value(beta, "beta"), scalar_value(gamma, "gamma")};
        if (certify) {
          if (shape.kind != ProfileKind::flat)
            throw InputError("certify=True with profile = " + py_repr(profile) +
                             ": a proven rig state exists for the flat punch (a curved contact's row shares one body)");
          try {
            rig_wave_input(w);
          } catch (const InputError& e) {
            throw InputError(std::string("certify=True: ") + e.what());
          }
        }
        RigReport r;
        std::optional<RigCertificate> cert;
        {
          py::gil_scoped_release release;
          r = evaluate_rig(w, point, spec, precision, {}, shape);
          if (certify) {
            try {
              cert = certify_rig(w, point, spec, precision, r.mu, shape);
            } catch (const InputError& e) {
              throw InputError(std::string("certify=True: ") + e.what());
            }
            if (!cert->mu.correctly_rounded)
              throw SolverError("certify=True: the value " + r.mu + " is not the correct rounding of the rig's proven value (that is " +
                                cert->mu.nearest.front() + "): a solver bug, please report it");
          }
        }
        const Converter convert(result_form(precision, strings), precision);
        char floquet[32];
        std::snprintf(floquet, sizeof floquet, "%.6g", r.floquet);
        py::dict d;
        for (const auto& [name, value] : std::vector<std::pair<const char*, std::string>>{
                 {"mu_over_mu0", r.mu}, {"stick_fraction", r.stick_fraction.text()}, {"slip_fraction", r.slip_fraction.text()},
                 {"backward_slip_fraction", r.backward_fraction.text()}, {"flight_fraction", r.flight_fraction.text()},
                 {"amplitude", r.amplitude.text()}, {"largest_backward_slip", r.largest_backward_slip.text()},
                 {"floquet_multiplier", floquet}, {"relative_error_estimate", r.relative_error.text()},
                 {"quasi_static_mu_over_mu0", r.quasi_static_mu}})
          d[py::str(name)] = convert(value);
        if (r.springs) d["springs"] = py::int_(r.springs);
        if (cert) {
          d["lower"] = to_fraction(cert->mu.lower);
          d["upper"] = to_fraction(cert->mu.upper);
          d["cite"] = py::str(cert->mu.cite);
          d["correctly_rounded"] = py::str("proven");
          for (const auto& [name, value] : rig_certificate_fields(*cert)) d[py::str(name)] = py::str(value);
        }
        if (!r.resonance_note.empty() && PyErr_WarnEx(PyExc_UserWarning, r.resonance_note.c_str(), 1) != 0)
          throw py::error_already_set();
        return d;
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "kappa"_a, "omega"_a, "zeta"_a = py::none(), "digits"_a = py::none(),
      "type"_a = py::none(), "strings"_a = false, "profile"_a = "flat", "certify"_a = false, R"doc(rig(wave, beta, gamma, *, kappa, omega, zeta=None, digits=None, type=None, strings=False, profile='flat', certify=False) -> dict

Rig dynamics at one point (the tool's mu --kappa --omega --zeta; model.md, "Rig dynamics"): a body
of mass m on a system spring k_s (damper c), kappa = k_s/k_x, omega = sqrt(k_x/m)/(2 pi f),
zeta = c/(2 sqrt(m k_s)). Returns the tool's fields, in its order: mu_over_mu0 (as mu() would),
stick_fraction, slip_fraction, flight_fraction (they add to 1), backward_slip_fraction (the part of
slip_fraction slipping backward), amplitude (half the peak-to-peak of X - beta phi) and
largest_backward_slip (both in units of mu0 k_z A/k_x), floquet_multiplier (0: below what
difference quotients resolve), relative_error_estimate (the two precisions apart) and
quasi_static_mu_over_mu0 (the paper's value at the same point; where the two differ by more than
10 %, a UserWarning names the rig's nearest resonance). Values as
mu(): float for type None/'double', or decimal strings with strings=True; the fractions carry
the digits the two precisions agree on. ValueError for bad input, vibrofric.SolverError where no
periodic state is found.

profile: a curved contact ('sphere', 'cone', 'power:N', 'wearflat:L', 'profile:FILE'; model.md,
"On a curved contact"): the body carries the whole MDR row, kappa and omega of k_x,max (every
spring touching); any gamma (the centre in contact all period too). The row is solved at n and 2n
springs: mu_over_mu0 and the fractions carry the digits the two agree on, and 'springs' is 2n.

certify=True (flat punch; the sine, Fourier series and piecewise-linear waves): the periodic state
proven by interval arithmetic (the tool's mu --kappa --omega --certify): also lower and upper
(fractions.Fraction, an enclosure of mu that proves mu_over_mu0 its correct rounding), cite,
correctly_rounded, periodic_state, section_phase, section_mode, state_lag_box,
state_lag_rate_box, the fractions' and the largest Floquet multiplier's enclosures ('[lo, hi]')
and stability. vibrofric.SolverError where no proof is found (naming the decision left open).
)doc");
}

}  // namespace vibrofric::python
