// The Python module `vibrofric` (pybind11): the library's evaluation, waves from arrays and the
// claims catalogue, for numpy users. μ̄/μ0 (Eq. 15) and Ψ_w(β) (Eq. 12) broadcast over β and γ like
// a scipy.special function; each batch is one call of the library's batch API, with the GIL
// released and the library's worker threads. Bad input is ValueError with the library's one-line
// message, a solver failure vibrofric.SolverError (an ArithmeticError); never NaN for a failure.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "vibrofric/arrays.hpp"
#include "vibrofric/catalogue.hpp"
#include "vibrofric/claims.hpp"
#include "vibrofric/errors.hpp"
#include "vibrofric/evaluate.hpp"
#include "vibrofric/profile.hpp"

namespace py = pybind11;
using namespace pybind11::literals;
using namespace vibrofric;

namespace {

// A wave or profile built from arrays (vibrofric.samples, vibrofric.fourier, vibrofric.profile).
struct PyWave {
  WaveSpec spec;
};
struct PyProfile {
  ProfileSpec spec;
};

std::string py_repr(const py::handle& x) { return py::repr(x).cast<std::string>(); }

WaveSpec to_wave(const py::object& w) {
  if (py::isinstance<py::str>(w)) return parse_wave(w.cast<std::string>());
  if (py::isinstance<PyWave>(w)) return w.cast<const PyWave&>().spec;
  throw py::type_error("wave = " + py_repr(w) +
                       ": expected a name such as 'sine', 'power:3', 'samples:FILE', or a Wave from "
                       "vibrofric.samples / vibrofric.fourier");
}

ProfileSpec to_profile(const py::object& p) {
  if (py::isinstance<py::str>(p)) return parse_profile(p.cast<std::string>());
  if (py::isinstance<PyProfile>(p)) return p.cast<const PyProfile&>().spec;
  throw py::type_error("profile = " + py_repr(p) +
                       ": expected a name such as 'flat', 'sphere', 'wearflat:0.5', or a Profile from vibrofric.profile");
}

// The decimal text of one Python number or string: floats by their shortest round-trip text (0.1
// is the decimal 0.1, as typed on the tool's command line), integers exactly, strings as given
// (exact decimals at any precision). Booleans and other types are refused.
std::string scalar_text(const py::handle& x, const std::string& what) {
  if (py::isinstance<py::str>(x)) return x.cast<std::string>();
  if (py::isinstance<py::bool_>(x) || py::isinstance(x, py::module_::import("numpy").attr("bool_")))
    throw py::type_error(what + " = " + py_repr(x) + ": expected a number or a decimal string, not a boolean");
  if (py::isinstance<py::int_>(x) || py::isinstance(x, py::module_::import("numpy").attr("integer")))
    return py::str(py::int_(py::reinterpret_borrow<py::object>(x))).cast<std::string>();
  if (py::isinstance<py::float_>(x) || py::isinstance(x, py::module_::import("numpy").attr("floating")))
    return decimal_text(py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>());
  if (py::hasattr(x, "__float__") && !py::isinstance(x, py::module_::import("numpy").attr("complexfloating")) &&
      !py::isinstance<py::bytes>(x)) {
    // mpmath.mpf, decimal.Decimal, fractions.Fraction: their own text when it is a decimal,
    // else the double.
    const std::string s = py::str(x).cast<std::string>();
    try {
      check_decimal(s, what);
      return s;
    } catch (const InputError&) {
      return decimal_text(py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>());
    }
  }
  throw py::type_error(what + " = " + py_repr(x) + ": expected a real number or a decimal string");
}

// A column of decimal texts from an array-like (flattened, C order). Float arrays go through
// decimal_text in C++ (the batch path: no Python object per element).
std::vector<std::string> column_texts(const py::array& a, const std::string& what) {
  const char kind = a.dtype().kind();
  const auto n = static_cast<std::size_t>(a.size());
  std::vector<std::string> out;
  out.reserve(n);
  if (kind == 'f') {
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const double* p = d.data();
    for (std::size_t i = 0; i < n; ++i) out.push_back(decimal_text(p[i]));
    return out;
  }
  if (kind == 'i' || kind == 'u') {
    if (kind == 'u' && a.dtype().itemsize() == 8) {
      const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
      for (std::size_t i = 0; i < n; ++i) out.push_back(std::to_string(u.data()[i]));
      return out;
    }
    const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (std::size_t i = 0; i < n; ++i) out.push_back(std::to_string(d.data()[i]));
    return out;
  }
  if (kind == 'U' || kind == 'S' || kind == 'O') {
    const py::array flat = py::module_::import("numpy").attr("ravel")(a.attr("astype")("object"));
    for (const auto& x : flat) out.push_back(scalar_text(x, what));
    return out;
  }
  throw py::type_error(what + " of dtype " + py::str(a.dtype()).cast<std::string>() +
                       ": expected real numbers or decimal strings");
}

std::vector<std::string> array_texts(const py::object& x, const std::string& what) {
  const py::array a = py::module_::import("numpy").attr("asarray")(x);
  if (a.ndim() > 1)
    throw py::value_error(what + " has " + std::to_string(a.ndim()) + " dimensions: expected a one-dimensional array");
  return column_texts(a, what);
}

struct Evaluation {
  Quantity quantity;
  std::optional<int> digits;
  py::object type;
  ProfileSpec profile;
  unsigned threads = 0;
  std::optional<long long> max_iterations;
  bool escalate = true;
  bool strings = false;
};

Precision to_precision(const std::optional<int>& digits, const py::object& type) {
  Precision p;
  if (!type.is_none() && !py::isinstance<py::str>(type))
    throw py::type_error("type = " + py_repr(type) + ": expected a string such as 'double' or 'mpfr'");
  const std::string t = type.is_none() ? (digits ? "mpfr" : "double") : type.cast<std::string>();
  try {
    p.type = parse_number_type(t);
  } catch (const InputError&) {
    throw InputError("type = " + py_repr(type) +
                     ": expected double, long-double, cpp_bin_float_50, cpp_bin_float_100 or mpfr");
  }
  if (digits) {
    if (p.type != NumberType::mpfr)
      throw InputError("digits = " + std::to_string(*digits) + " with type = '" + t +
                       "': digits apply to type 'mpfr' (the default when digits are given)");
    if (*digits < min_digits || *digits > max_digits)
      throw InputError("digits = " + std::to_string(*digits) + ": expected " + std::to_string(min_digits) + " to " +
                       std::to_string(max_digits) + " significant digits");
    p.digits = *digits;
  } else if (p.type == NumberType::mpfr) {
    p.digits = 50;  // as the tool
  }
  return p;
}

template <class Real>
Real read_decimal(const std::string& s) {
  Real x{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size())
    throw SolverError("the library returned '" + s + "', not a decimal number");  // never expected
  return x;
}

// Values of `quantity` at the broadcast of beta and gamma (gamma None for psi).
py::object evaluate_broadcast(const py::object& wave_obj, const py::object& beta, const py::object& gamma,
                              const Evaluation& e) {
  const py::module_ np = py::module_::import("numpy");
  const WaveSpec wave = to_wave(wave_obj);
  const Precision precision = to_precision(e.digits, e.type);
  BatchOptions options;
  options.profile = e.profile;
  options.threads = e.threads;
  options.escalate = e.escalate;
  if (e.max_iterations) {
    if (*e.max_iterations < 1 || *e.max_iterations > 100000)
      throw InputError("max_iterations = " + std::to_string(*e.max_iterations) + ": expected 1 to 100000");
    options.solver.max_root_iterations = static_cast<std::uintmax_t>(*e.max_iterations);
  }

  const py::array b = np.attr("asarray")(beta);
  const bool with_gamma = e.quantity == Quantity::mu;
  py::array g = with_gamma ? py::array(np.attr("asarray")(gamma)) : py::array(np.attr("asarray")(0.0));
  const py::tuple both = np.attr("broadcast_arrays")(b, g);  // ValueError if the shapes do not broadcast
  const py::array bb = both[0], gb = both[1];
  const py::tuple shape = bb.attr("shape");
  const bool scalar = bb.ndim() == 0;

  std::vector<std::string> betas = column_texts(np.attr("ascontiguousarray")(bb), "beta");
  std::vector<std::string> gammas = with_gamma ? column_texts(np.attr("ascontiguousarray")(gb), "gamma")
                                               : std::vector<std::string>();
  std::vector<Point> points(betas.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].beta = std::move(betas[i]);
    if (with_gamma) points[i].gamma = std::move(gammas[i]);
  }

  std::vector<std::string> values;
  {
    py::gil_scoped_release release;
    values = evaluate(wave, e.quantity, points, precision, options);
  }

  const std::size_t n = values.size();
  const auto as_scalar_or_shaped = [&](py::array flat) -> py::object {
    if (scalar) return flat[py::int_(0)];
    return flat.attr("reshape")(shape);
  };
  if (!e.strings && precision.type == NumberType::float64) {
    py::array_t<double> out(static_cast<py::ssize_t>(n));
    double* p = out.mutable_data();
    for (std::size_t i = 0; i < n; ++i) p[i] = read_decimal<double>(values[i]);
    if (scalar) return py::float_(p[0]);
    return out.attr("reshape")(shape);
  }
  if (!e.strings && precision.type == NumberType::float80) {
    py::array_t<long double> out(static_cast<py::ssize_t>(n));
    long double* p = out.mutable_data();
    for (std::size_t i = 0; i < n; ++i) p[i] = read_decimal<long double>(values[i]);
    return as_scalar_or_shaped(out);
  }
  // Decimal strings, or mpmath.mpf holding every digit when mpmath is importable.
  py::object mpf, workdps;
  if (!e.strings) {
    try {
      const py::module_ mpmath = py::module_::import("mpmath");
      mpf = mpmath.attr("mpf");
      workdps = mpmath.attr("workdps");
    } catch (const py::error_already_set&) {
      mpf = py::none();
    }
  }
  py::array out = np.attr("empty")(n, "dtype"_a = "object");
  auto set = [&](std::size_t i, py::object v) { out[py::int_(i)] = std::move(v); };
  if (mpf && !mpf.is_none()) {
    const py::object context = workdps(output_digits(precision) + 3);
    context.attr("__enter__")();
    try {
      for (std::size_t i = 0; i < n; ++i) set(i, mpf(values[i]));
    } catch (...) {
      context.attr("__exit__")(py::none(), py::none(), py::none());
      throw;
    }
    context.attr("__exit__")(py::none(), py::none(), py::none());
  } else {
    for (std::size_t i = 0; i < n; ++i) set(i, py::str(values[i]));
  }
  return as_scalar_or_shaped(out);
}

py::dict claim_dict(const ClaimCheck& c) {
  py::dict d;
  d["key"] = c.key;
  d["id"] = c.id;
  d["source"] = c.source;
  d["statement"] = c.statement;
  d["method"] = c.method;
  d["how"] = c.how;
  d["criterion"] = c.criterion;
  d["proof"] = c.proof;
  d["worst"] = c.worst;
  d["verdict"] = verdict_name(c.verdict);
  d["scope"] = c.scope;
  d["fails_where"] = c.fails_where;
  d["corrected"] = c.corrected;
  d["cases"] = c.cases;
  d["deviation"] = c.deviation_text;
  d["deviation_unit"] = c.deviation_unit;
  d["corrected_deviation"] = c.corrected_deviation ? py::object(py::str(c.corrected_deviation_text)) : py::object(py::none());
  py::list measured;
  for (const auto& m : c.measured) measured.append(py::make_tuple(m.name, m.value));
  d["measured"] = measured;
  d["digits"] = c.digits;
  return d;
}

std::optional<int> optional_int(const py::object& x, const char* what) {
  if (x.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(x) || !(py::isinstance<py::int_>(x) || py::hasattr(x, "__index__")))
    throw py::type_error(std::string(what) + " = " + py_repr(x) + ": expected an integer");
  const long long v = py::int_(x).cast<long long>();
  if (v < -1000000000LL || v > 1000000000LL)
    throw InputError(std::string(what) + " = " + std::to_string(v) + ": out of range");
  return static_cast<int>(v);
}

unsigned to_threads(const py::object& x) {
  const auto t = optional_int(x, "threads");
  if (!t) return 0;
  if (*t < 0 || *t > 4096) throw InputError("threads = " + std::to_string(*t) + ": expected 0 (all cores) to 4096");
  return static_cast<unsigned>(*t);
}

constexpr const char* mu_doc = R"doc(mu(wave, beta, gamma, *, profile="flat", digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False)

The macroscopic coefficient of friction mu/mu0 = int s dphi / int n dphi (Eq. 15; Eqs. 9, 13 of
the paper) for sliding velocity beta (Eq. 5) and mean indentation gamma = u/A (Eq. 14), in the
periodic steady state; curved indenters (profile) by the method of dimensionality reduction.

wave      a name -- 'sine' (harmonic), 'triangle', 'sawtooth-right', 'sawtooth-left', 'square',
          'power:P', 'samples:FILE', 'fourier:FILE' -- or a Wave from samples() / fourier().
beta      > 0; gamma: contact requires gamma + max w > 0 (gamma > -1 for the catalogue waves).
          Scalars, arrays or nested sequences; they broadcast like numpy ufunc arguments.
          Floats mean their shortest decimal text (0.1 is the decimal 0.1, as on the tool's
          command line); decimal strings are exact at any precision.
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

Scalar arguments give a scalar. Raises ValueError (bad input, gamma without contact, beta <= 0)
and vibrofric.SolverError (the solver did not converge); never returns NaN for a failure.
)doc";

constexpr const char* psi_doc = R"doc(psi(wave, beta, *, digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False)

The reduction function Psi_w(beta) = int (n - s) dphi without jumping (Eq. 12), which does not
depend on gamma, so that mu/mu0 = 1 - Psi_w(beta)/gamma for gamma >= 1 (Eq. 13). For the
triangle Psi = (4 - beta)/(4 + beta) (Eq. 17). Arguments and results as mu(); beta broadcasts.
Flat punch only (Psi does not exist for curved profiles).
)doc";

}  // namespace

PYBIND11_MODULE(vibrofric, m) {
  py::options options;
  options.disable_function_signatures();  // each docstring opens with its Python signature
  m.doc() = R"doc(vibrofric: sliding friction under large-amplitude normal oscillation.

The contact-mechanical theory of M. Popov, "Friction under large-amplitude normal oscillations",
on the C++ library vibrofric: mu() is mu/mu0 (Eq. 15), psi() the reduction function Psi_w(beta)
(Eq. 12), samples() / fourier() user waves from arrays, profile() a measured indenter, verify()
the paper's claims. Results are correctly rounded doubles, or exact decimals at any precision.
)doc";
#ifdef VIBROFRIC_VERSION
  m.attr("__version__") = VIBROFRIC_VERSION;
#endif

  static py::exception<SolverError> solver_error(m, "SolverError", PyExc_ArithmeticError);
  solver_error.doc() =
      "The solver did not converge (a root finder or quadrature over its budget, or a precision that "
      "cannot resolve the problem without escalation). A subclass of ArithmeticError.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {  // DomainError too
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SolverError& e) {  // PrecisionError too
      PyErr_SetString(solver_error.ptr(), e.what());
    }
  });

  py::class_<PyWave>(m, "Wave", "A waveform built from arrays by vibrofric.samples or vibrofric.fourier.")
      .def_property_readonly("name", [](const PyWave& w) { return w.spec.name; })
      .def_property_readonly("kind", [](const PyWave& w) {
        return w.spec.kind == WaveKind::samples ? std::string("samples") : std::string("fourier");
      })
      .def("__len__", [](const PyWave& w) {
        return w.spec.kind == WaveKind::samples ? w.spec.samples.size() : w.spec.harmonics.size();
      })
      .def("__repr__", [](const PyWave& w) {
        return w.spec.kind == WaveKind::samples
                   ? "<vibrofric.Wave samples: " + std::to_string(w.spec.samples.size()) + " values" +
                         (w.spec.times.empty() ? std::string("") : std::string(", time column")) + ">"
                   : "<vibrofric.Wave fourier: " + std::to_string(w.spec.harmonics.size()) + " harmonics>";
      });
  py::class_<PyProfile>(m, "Profile", "A measured axisymmetric indenter profile built by vibrofric.profile.")
      .def_property_readonly("name", [](const PyProfile& p) { return p.spec.name; })
      .def("__len__", [](const PyProfile& p) { return p.spec.r.size(); })
      .def("__repr__", [](const PyProfile& p) {
        return "<vibrofric.Profile measured: " + std::to_string(p.spec.r.size()) + " samples>";
      });

  m.def(
      "samples",
      [](const py::object& y, const py::object& t) {
        const auto ys = array_texts(y, "y");
        const auto ts = t.is_none() ? std::vector<std::string>() : array_texts(t, "t");
        return PyWave{samples_wave(ys, ts, "samples")};
      },
      "y"_a, "t"_a = py::none(),
      R"doc(samples(y, t=None) -> Wave

A sampled periodic signal, linear between the samples, normalised to zero mean and
max w - min w = 2 (model.md, "Waveform catalogue"). Without t: y_0 ... y_{N-1} at phi = j/N, one
period without its end point (N >= 2). With t: time stamps t_0 ... t_N, strictly increasing, and
y_N = y_0 (one period with its end point; t_N - t_0 is the period). Exactly as the same numbers in a
samples:FILE (floats by their shortest decimal text; strings exact); ValueError for what such a
file would be refused for (NaN, ragged t and y, a constant signal, repeated periods).
)doc");
  m.def(
      "fourier",
      [](const py::object& a, const py::object& b, const py::object& a0) {
        const auto as = array_texts(a, "a");
        const auto bs = array_texts(b, "b");
        const std::string a0s = a0.is_none() ? std::string() : scalar_text(a0, "a0");
        if (!a0.is_none() && a0s.empty()) throw InputError("a0 is empty: expected a decimal number");
        return PyWave{fourier_wave(as, bs, a0s, "fourier")};
      },
      "a"_a, "b"_a, "a0"_a = py::none(),
      R"doc(fourier(a, b, a0=None) -> Wave

The finite Fourier series w = a0 + sum_k a_k cos(2 pi k phi) + b_k sin(2 pi k phi) with
a = (a_1 ... a_K), b = (b_1 ... b_K); a0 is the mean and is removed, the series normalised to
max w - min w = 2. Exactly as a fourier:FILE of lines 'k a_k b_k'.
)doc");
  m.def(
      "profile",
      [](const py::object& r, const py::object& f) {
        return PyProfile{profile_arrays(array_texts(r, "r"), array_texts(f, "f"), "profile")};
      },
      "r"_a, "f"_a,
      R"doc(profile(r, f) -> Profile

A measured axisymmetric indenter f(r) (MDR, model.md "Curved contacts"): r from 0, increasing;
f(0) = 0, non-decreasing and convex; heights in units of the amplitude A. Exactly as a
profile:FILE of lines 'r f'.
)doc");

  m.def(
      "mu",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& profile,
         const py::object& digits, const py::object& type, const py::object& threads, const py::object& max_iterations,
         bool escalate, bool strings) {
        Evaluation e;
        e.quantity = Quantity::mu;
        e.digits = optional_int(digits, "digits");
        e.type = type;
        e.profile = to_profile(profile);
        e.threads = to_threads(threads);
        if (auto mi = optional_int(max_iterations, "max_iterations")) e.max_iterations = *mi;
        e.escalate = escalate;
        e.strings = strings;
        return evaluate_broadcast(wave, beta, gamma, e);
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "profile"_a = "flat", "digits"_a = py::none(),
      "type"_a = py::none(), "threads"_a = 0, "max_iterations"_a = py::none(), "escalate"_a = true,
      "strings"_a = false, mu_doc);

  m.def(
      "psi",
      [](const py::object& wave, const py::object& beta, const py::object& digits, const py::object& type,
         const py::object& threads, const py::object& max_iterations, bool escalate, bool strings) {
        Evaluation e;
        e.quantity = Quantity::psi;
        e.digits = optional_int(digits, "digits");
        e.type = type;
        e.threads = to_threads(threads);
        if (auto mi = optional_int(max_iterations, "max_iterations")) e.max_iterations = *mi;
        e.escalate = escalate;
        e.strings = strings;
        return evaluate_broadcast(wave, beta, py::none(), e);
      },
      "wave"_a, "beta"_a, py::kw_only(), "digits"_a = py::none(), "type"_a = py::none(), "threads"_a = 0,
      "max_iterations"_a = py::none(), "escalate"_a = true, "strings"_a = false, psi_doc);

  m.def(
      "verify",
      [](const py::object& claim, const py::object& digits_obj) {
        const auto digits = optional_int(digits_obj, "digits");
        const int d = digits ? *digits : 50;
        if (d < 10 || d > 300)
          throw InputError("digits = " + std::to_string(d) + ": expected 10 to 300 (the range over which the verdicts are tested)");
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
        py::list out;
        for (const auto& c : checks) out.append(claim_dict(c));
        return out;
      },
      "claim"_a = py::none(), "digits"_a = 50,
      R"doc(verify(claim=None, digits=50) -> list of dict

Decides the paper's claims (model.md, "The paper's claims that the suite verifies") with the
high-precision solver at `digits` (10 to 300) plus guard digits, as `vibrofric verify --format
json`: one dict per claim with key, id, source, statement, method, how, criterion, proof, worst,
verdict ('holds', 'holds approximately', 'fails'), scope, fails_where, corrected, cases,
deviation (decimal string), deviation_unit, corrected_deviation (None without a corrected
statement), measured (list of (name, value)) and digits. claim: one key ('eq17', 'eq24', ...);
None runs every claim (minutes). ValueError for an unknown key.
)doc");

  m.attr("catalogue") = py::cast(catalogue_names());
  py::list keys;
  for (const auto& c : claims_catalogue()) keys.append(c.key);
  m.attr("claims") = keys;
}
