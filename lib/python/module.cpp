// The Python module `vibrofric` (pybind11): the library's evaluation, waves from arrays and the
// claims catalogue, for numpy users. μ̄/μ0 (Eq. 15) and Ψ_w(β) (Eq. 12) broadcast over β and γ like
// a scipy.special function; each batch is one call of the library's batch API, with the GIL
// released and the library's worker threads. Bad input is ValueError with the library's one-line
// message, a solver failure vibrofric.SolverError (an ArithmeticError); never NaN for a failure.
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <vector>

#include "vibrofric/api/arrays.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/certify.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/fit.hpp"
#include "vibrofric/api/profile_spec.hpp"
#include "vibrofric/api/rig.hpp"
#include "vibrofric/api/suggest.hpp"
#include "vibrofric/verification/claims.hpp"

namespace py = pybind11;
using namespace pybind11::literals;
using namespace vibrofric;

namespace {

// A wave (vibrofric.wave, samples, fourier, fit) or a profile built from arrays (vibrofric.profile).
// A fitted wave keeps its fit (coefficients as written, method, residuals) and the name of what
// was fitted, for fourier_text().
struct PyWave {
  WaveSpec spec;
  std::shared_ptr<const FourierFit> fit;
  std::string fitted;
};
struct PyProfile {
  ProfileSpec spec;
};

std::string py_repr(const py::handle& x) { return py::repr(x).cast<std::string>(); }

// Pickle states (Wave and Profile cross to other processes: multiprocessing, concurrent.futures,
// Dask): every field as written, so a wave read from a file needs no file where it is unpickled,
// and the wave unpickled is the same wave, value for value. The first item is the state's version.
py::list text_list(const std::vector<std::string>& v) {
  py::list out;
  for (const auto& x : v) out.append(x);
  return out;
}
std::vector<std::string> texts_of(const py::handle& l) { return l.cast<std::vector<std::string>>(); }
py::list harmonic_list(const std::vector<WaveSpec::Harmonic>& hs) {
  py::list out;
  for (const auto& h : hs) out.append(py::make_tuple(h.k, h.a, h.b));
  return out;
}
std::vector<WaveSpec::Harmonic> harmonics_of(const py::handle& l) {
  std::vector<WaveSpec::Harmonic> out;
  for (const auto& h : l.cast<py::list>()) {
    const auto t = h.cast<py::tuple>();
    out.push_back({t[0].cast<unsigned>(), t[1].cast<std::string>(), t[2].cast<std::string>()});
  }
  return out;
}
constexpr int pickle_version = 1;
void check_state(const py::tuple& t, std::size_t size, const char* what) {
  if (t.size() != size || t[0].cast<int>() != pickle_version)
    throw InputError(std::string("unpickling a ") + what + ": a state of " + std::to_string(t.size()) +
                     " items, expected version " + std::to_string(pickle_version) + " with " + std::to_string(size));
}

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

// The element's error, its message led by its index as numpy.unravel_index writes it ("at index
// (2,): ", "(1, 0)"); a scalar call's (dims empty) as it is.
[[noreturn]] void rethrow_at_index(const std::vector<std::size_t>& dims, std::size_t i, const std::exception_ptr& error) {
  std::string where;
  if (!dims.empty()) {
    std::vector<std::size_t> at(dims.size());
    for (std::size_t k = dims.size(); k-- > 0;) {
      at[k] = i % dims[k];
      i /= dims[k];
    }
    for (std::size_t k = 0; k < at.size(); ++k) where += (k ? ", " : "(") + std::to_string(at[k]);
    where = "at index " + where + (at.size() == 1 ? ",): " : "): ");
  }
  try {
    std::rethrow_exception(error);
  } catch (const DomainError& e) {
    throw DomainError(where + e.what());
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  } catch (const PrecisionError& e) {
    throw PrecisionError(where + e.what());
  } catch (const SolverError& e) {
    throw SolverError(where + e.what());
  }
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
  bool nan_on_error = false;
  bool certify = false;
  std::string profile_text;  // as given, for messages
  std::optional<RigSpec> rig;  // kappa, omega, zeta (rig dynamics)
};

Precision to_precision(const std::optional<int>& digits, const py::object& type) {
  Precision p;
  if (!type.is_none() && !py::isinstance<py::str>(type))
    throw py::type_error("type = " + py_repr(type) + ": expected a string such as 'double' or 'mpfr'");
  const std::string t = type.is_none() ? (digits ? "mpfr" : "double") : type.cast<std::string>();
  const auto named = number_type_named(t);
  if (!named) {
    const std::string hint = did_you_mean(t, number_type_names());
    throw InputError("type = " + py_repr(type) + ": expected " + number_type_choices + (hint.empty() ? "" : "; " + hint));
  }
  p.type = *named;
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

// How values come back: float64 and numpy.longdouble for the hardware types, otherwise mpmath.mpf
// (created at the printed digits + 3) when mpmath is importable, else the library's decimal
// strings; strings=True gives the strings for every type. mu and psi store the value the stream
// delivers (StreamValue::number); the API's other outputs (physical, normalisation, trace) are
// decimal by definition, their digits computed at a higher precision, and a float is the nearest
// one to the printed decimal (from_chars), as Python's float() of the tool's output.
enum class Form { float64, float80, mpf, text };

Form result_form(const Precision& p, bool strings) {
  if (strings) return Form::text;
  if (p.type == NumberType::float64) return Form::float64;
  if (p.type == NumberType::float80) return Form::float80;
  try {
    py::module_::import("mpmath");
    return Form::mpf;
  } catch (const py::error_already_set&) {
    return Form::text;
  }
}

// Python objects for the library's decimal texts in one Form; for mpf, mpmath's working precision
// while this lives. Constructed, used and destroyed with the GIL held.
class Converter {
 public:
  Converter(Form form, const Precision& p) : form_(form) {
    if (form != Form::mpf) return;
    const py::module_ mpmath = py::module_::import("mpmath");
    mpf_ = mpmath.attr("mpf");
    context_ = mpmath.attr("workdps")(output_digits(p) + 3);
    context_.attr("__enter__")();
  }
  ~Converter() {
    if (!context_) return;
    try {
      context_.attr("__exit__")(py::none(), py::none(), py::none());
    } catch (const py::error_already_set&) {  // a destructor cannot throw; mpmath's __exit__ does not fail
    }
  }
  Converter(const Converter&) = delete;
  Converter& operator=(const Converter&) = delete;

  Form form() const { return form_; }

  py::object operator()(const std::string& s) const {
    switch (form_) {
      case Form::float64: return py::float_(read_decimal<double>(s));
      case Form::float80: {
        py::array_t<long double> one(1);
        one.mutable_data()[0] = read_decimal<long double>(s);
        return one[py::int_(0)];
      }
      case Form::mpf: return mpf_(s);
      case Form::text: break;
    }
    return py::str(s);
  }

 private:
  Form form_;
  py::object mpf_, context_;
};

// One argument of a batch (beta or gamma) as numpy gives it, before broadcasting: its values in C
// order, read by index as the decimal text a file would hold (decimal_text for floats, exact
// integers, strings as given). text() reads only C++ memory: the worker threads call it without
// the GIL. Texts are made ahead (on the calling thread, one per element of the argument, not of
// the broadcast) only for strings and Python objects.
class Column {
 public:
  Column(const py::array& a, const std::string& what) {
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape_.push_back(static_cast<std::size_t>(a.shape(k)));
    const char kind = a.dtype().kind();
    if (kind == 'f') {
      const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
      holder_ = d;
      reals_ = d.data();
    } else if (kind == 'u' && a.dtype().itemsize() == 8) {
      const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
      holder_ = u;
      unsigneds_ = u.data();
    } else if (kind == 'i' || kind == 'u') {
      const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
      holder_ = d;
      integers_ = d.data();
    } else if (kind == 'U' || kind == 'S' || kind == 'O') {
      const py::array flat = py::module_::import("numpy").attr("ravel")(a.attr("astype")("object"));
      for (const auto& x : flat) texts_.push_back(scalar_text(x, what));
    } else {
      throw py::type_error(what + " of dtype " + py::str(a.dtype()).cast<std::string>() +
                           ": expected real numbers or decimal strings");
    }
  }
  const std::vector<std::size_t>& shape() const { return shape_; }
  std::string text(std::size_t j) const {
    if (reals_) return decimal_text(reals_[j]);
    if (integers_) return std::to_string(integers_[j]);
    if (unsigneds_) return std::to_string(unsigneds_[j]);
    return texts_[j];
  }

 private:
  std::vector<std::size_t> shape_;
  py::array holder_;  // keeps the converted data alive
  const double* reals_ = nullptr;
  const std::int64_t* integers_ = nullptr;
  const std::uint64_t* unsigneds_ = nullptr;
  std::vector<std::string> texts_;
};

// Point i of the broadcast (C order over the result's shape) to the flat indices of beta and gamma
// in their own arrays: numpy's broadcasting rules (shapes aligned at the right, size 1 repeats).
class BroadcastIndex {
 public:
  BroadcastIndex(const std::vector<std::size_t>& shape, const std::vector<std::size_t>& a,
                 const std::vector<std::size_t>& b)
      : shape_(shape), strides_(shape.size(), {0, 0}) {
    place(a, 0);
    place(b, 1);
  }
  std::array<std::size_t, 2> operator()(std::size_t i) const {
    std::array<std::size_t, 2> at{0, 0};
    for (std::size_t k = shape_.size(); k-- > 0;) {
      const std::size_t index = i % shape_[k];
      i /= shape_[k];
      at[0] += index * strides_[k][0];
      at[1] += index * strides_[k][1];
    }
    return at;
  }

 private:
  void place(const std::vector<std::size_t>& s, int which) {
    std::size_t stride = 1;
    for (std::size_t k = s.size(); k-- > 0;) {
      const std::size_t out = shape_.size() - s.size() + k;
      strides_[out][which] = s[k] == 1 ? 0 : stride;
      stride *= s[k];
    }
  }
  std::vector<std::size_t> shape_;
  std::vector<std::array<std::size_t, 2>> strides_;
};

// The result array of a batch, filled by evaluate_stream's sink (index order, calling thread) while
// the GIL is released: float64 and long double straight into the array; Python objects (mpf, str)
// gathered a few hundred at a time and stored under the GIL. Nothing holds all the values' texts.
class Output {
 public:
  // dims: the result's shape (a failing element's error names its index in it); nan_on_error:
  // a failing element is NaN (None in object arrays) instead.
  Output(const Converter& convert, std::size_t n, std::vector<std::size_t> dims, bool nan_on_error)
      : convert_(convert), dims_(std::move(dims)), nan_on_error_(nan_on_error) {
    switch (convert.form()) {
      case Form::float64: {
        py::array_t<double> a(static_cast<py::ssize_t>(n));
        doubles_ = a.mutable_data();
        array_ = a;
        break;
      }
      case Form::float80: {
        py::array_t<long double> a(static_cast<py::ssize_t>(n));
        long_doubles_ = a.mutable_data();
        array_ = a;
        break;
      }
      default: {
        array_ = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");  // None each
        objects_ = static_cast<PyObject**>(array_.mutable_data());
        pending_.reserve(batch);
      }
    }
  }
  // Without the GIL. float64 and long double store the number the stream delivers (the value its
  // text prints, held exactly); the other forms are made from the text.
  void put(std::size_t i, const StreamValue& value) {
    if (value.error) {
      if (!nan_on_error_) rethrow_at(i, value.error);
      if (doubles_) doubles_[i] = std::numeric_limits<double>::quiet_NaN();
      if (long_doubles_) long_doubles_[i] = std::numeric_limits<long double>::quiet_NaN();
      return;  // an object array's element stays None
    }
    if (doubles_) {
      doubles_[i] = static_cast<double>(value.number.value());
    } else if (long_doubles_) {
      long_doubles_[i] = value.number.value();
    } else {
      pending_.emplace_back(i, value.text);
      if (pending_.size() == batch) flush();
    }
  }
  // Stores the gathered objects, taking the GIL for it.
  void flush() {
    if (pending_.empty()) return;
    py::gil_scoped_acquire acquire;
    for (const auto& [i, value] : pending_) {
      PyObject* old = objects_[i];
      objects_[i] = convert_(value).release().ptr();
      Py_XDECREF(old);
    }
    pending_.clear();
  }
  const py::array& array() const { return array_; }

 private:
  [[noreturn]] void rethrow_at(std::size_t i, const std::exception_ptr& error) const { rethrow_at_index(dims_, i, error); }
  static constexpr std::size_t batch = 512;
  const Converter& convert_;
  std::vector<std::size_t> dims_;
  bool nan_on_error_ = false;
  py::array array_;
  double* doubles_ = nullptr;
  long double* long_doubles_ = nullptr;
  PyObject** objects_ = nullptr;
  std::vector<std::pair<std::size_t, std::string>> pending_;
};

// certify=True (certify.hpp): each point computed as without it, and proven the correct rounding
// of its exact value (piecewise-linear waves, flat punch); the result is (lo, hi) of
// fractions.Fraction, equal, the exact value (arrays of them for array arguments).
py::object certify_broadcast(const WaveSpec& wave, const Precision& precision, const BatchOptions& options,
                             const Column& betas, const Column& gammas, const BroadcastIndex& index, std::size_t n,
                             const std::vector<std::size_t>& dims, const py::tuple& shape, const Evaluation& e) {
  std::optional<Certifier> certifier;
  if (options.profile.kind != ProfileKind::flat)
    throw InputError("certify=True with profile = " + e.profile_text +
                     ": certified values exist for the flat punch only (a curved contact integrates over springs)");
  if (e.nan_on_error)
    throw InputError("certify=True gives exact values or raises, nan_on_error=True gives NaN for a failure: give one of them");
  if (!options.escalate)
    throw InputError("certify=True proves the guaranteed value, escalate=False gives one that is not guaranteed: give one of them");
  try {
    certifier.emplace(wave, options.profile);
  } catch (const InputError& err) {
    throw InputError(std::string("certify=True: ") + err.what());
  }
  const bool with_gamma = e.quantity == Quantity::mu;
  auto point = [&](std::size_t i) {
    const auto at = index(i);
    Point p;
    p.beta = betas.text(at[0]);
    if (with_gamma) p.gamma = gammas.text(at[1]);
    return p;
  };
  std::vector<std::pair<exact::Rational, exact::Rational>> values(n);
  {
    py::gil_scoped_release release;
    evaluate_stream(wave, e.quantity, n, point, precision, options, [&](std::size_t i, const StreamValue& value) {
      if (value.error) rethrow_at_index(dims, i, value.error);
      const Certificate c = (*certifier)(e.quantity, point(i), precision, value.text);
      if (!c.correctly_rounded)
        rethrow_at_index(dims, i, std::make_exception_ptr(SolverError(
            "certify=True: the value " + value.text + " is not the correct rounding of the exact value " + c.exact +
            " (that is " + c.nearest.front() + "): a solver bug, please report it")));
      values[i] = {c.lower, c.upper};
    });
  }
  const py::object fraction = py::module_::import("fractions").attr("Fraction");
  const py::object integer = py::module_::import("builtins").attr("int");
  auto to_fraction = [&](const exact::Rational& x) {
    return fraction(integer(numerator(x).str()), integer(denominator(x).str()));
  };
  if (dims.empty()) {
    return py::make_tuple(to_fraction(values.front().first), to_fraction(values.front().second));
  }
  const py::module_ np = py::module_::import("numpy");
  py::array lo = np.attr("empty")(n, "dtype"_a = "object"), hi = np.attr("empty")(n, "dtype"_a = "object");
  for (std::size_t i = 0; i < n; ++i) {
    lo[py::int_(i)] = to_fraction(values[i].first);
    hi[py::int_(i)] = to_fraction(values[i].second);
  }
  return py::make_tuple(lo.attr("reshape")(shape), hi.attr("reshape")(shape));
}

// Values of `quantity` at the broadcast of beta and gamma (gamma None for psi): one evaluate_stream
// over the points, each made from the arguments by index on the worker threads, each value stored
// into the result as it arrives, the GIL released throughout.
py::object evaluate_broadcast(const py::object& wave_obj, const py::object& beta, const py::object& gamma,
                              const Evaluation& e) {
  const py::module_ np = py::module_::import("numpy");
  const WaveSpec wave = to_wave(wave_obj);
  const Precision precision = to_precision(e.digits, e.type);
  BatchOptions options;
  options.profile = e.profile;
  options.threads = e.threads;
  options.escalate = e.escalate;
  options.rig = e.rig;
  if (e.max_iterations) {
    if (*e.max_iterations < 1 || *e.max_iterations > root_iterations_limit)
      throw InputError("max_iterations = " + std::to_string(*e.max_iterations) + ": expected 1 to " +
                       std::to_string(root_iterations_limit));
    options.solver.max_root_iterations = static_cast<std::uintmax_t>(*e.max_iterations);
  }

  const bool with_gamma = e.quantity == Quantity::mu;
  const py::array b = np.attr("asarray")(beta);
  const py::array g = np.attr("asarray")(with_gamma ? gamma : py::object(py::float_(0.0)));
  const py::tuple shape = np.attr("broadcast")(b, g).attr("shape");  // ValueError if they do not broadcast
  std::vector<std::size_t> dims;
  std::size_t n = 1;
  for (const auto& d : shape) {
    dims.push_back(d.cast<std::size_t>());
    n *= dims.back();
  }
  const Column betas(b, "beta");
  const Column gammas(g, "gamma");  // psi: 0.0, never read
  const BroadcastIndex index(dims, betas.shape(), gammas.shape());

  options.deliver_errors = true;
  if (e.certify) return certify_broadcast(wave, precision, options, betas, gammas, index, n, dims, shape, e);
  const Converter convert(result_form(precision, e.strings), precision);
  Output out(convert, n, dims, e.nan_on_error);
  {
    py::gil_scoped_release release;
    evaluate_stream(
        wave, e.quantity, n,
        [&](std::size_t i) {
          const auto at = index(i);
          Point p;
          p.beta = betas.text(at[0]);
          if (with_gamma) p.gamma = gammas.text(at[1]);
          return p;
        },
        precision, options, [&](std::size_t i, const StreamValue& value) { out.put(i, value); });
    out.flush();
  }
  const py::array& flat = out.array();
  if (dims.empty()) {
    if (convert.form() == Form::float64) return py::float_(static_cast<const double*>(flat.data())[0]);
    return flat[py::int_(0)];
  }
  return flat.attr("reshape")(shape);
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

// periods= of wave() and samples(): None is 0 (one period, checked), else 1 to max_record_periods.
int record_periods(const py::object& periods) {
  const auto k = optional_int(periods, "periods");
  if (!k) return 0;
  if (*k < 1) throw InputError("periods = " + std::to_string(*k) + ": expected an integer from 1 to " +
                               std::to_string(max_record_periods));
  return *k;
}

unsigned to_threads(const py::object& x) {
  const auto t = optional_int(x, "threads");
  if (!t) return 0;
  if (*t < 0 || *t > static_cast<long long>(max_threads))
    throw InputError("threads = " + std::to_string(*t) + ": expected 0 (all cores) to " + std::to_string(max_threads));
  return static_cast<unsigned>(*t);
}

constexpr const char* mu_doc = R"doc(mu(wave, beta, gamma, *, profile="flat", digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False, nan_on_error=False, certify=False, kappa=None, omega=None, zeta=None)

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
lo < hi are the ends of an interval computation. Curved profiles raise ValueError.
)doc";

constexpr const char* psi_doc = R"doc(psi(wave, beta, *, digits=None, type=None, threads=0, max_iterations=None, escalate=True, strings=False, nan_on_error=False, certify=False)

The reduction function Psi_w(beta) = int (n - s) dphi without jumping (Eq. 12), which does not
depend on gamma, so that mu/mu0 = 1 - Psi_w(beta)/gamma for gamma >= 1 (Eq. 13). For the
triangle Psi = (4 - beta)/(4 + beta) (Eq. 17). Arguments and results as mu() (certify=True
too); beta broadcasts.
Flat punch only (Psi does not exist for curved profiles).
)doc";

BatchOptions solver_controls(const py::object& max_iterations, bool escalate) {
  BatchOptions options;
  options.escalate = escalate;
  if (const auto mi = optional_int(max_iterations, "max_iterations")) {
    if (*mi < 1 || *mi > root_iterations_limit)
      throw InputError("max_iterations = " + std::to_string(*mi) + ": expected 1 to " + std::to_string(root_iterations_limit));
    options.solver.max_root_iterations = static_cast<std::uintmax_t>(*mi);
  }
  return options;
}

std::string kind_name(WaveKind k) {
  switch (k) {
    case WaveKind::sine: return "sine";
    case WaveKind::triangle: return "triangle";
    case WaveKind::sawtooth_right: return "sawtooth-right";
    case WaveKind::sawtooth_left: return "sawtooth-left";
    case WaveKind::square: return "square";
    case WaveKind::power: return "power";
    case WaveKind::fourier: return "fourier";
    case WaveKind::samples: return "samples";
  }
  return "unknown";
}

bool is_decimal(const std::string& s) {
  try {
    check_decimal(s, "value");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// `physical` (commands.hpp): the inputs as decimal texts of the Python values, named by their
// keywords; the outputs by name, shape a string and the rest in the Form of the precision.
py::dict physical_dict(const WaveSpec& wave, const PhysicalRequest& request, const Precision& precision,
                       const BatchOptions& options, bool strings) {
  PhysicalOutputs record;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release release;
    record = physical_point(wave, request, precision, options, &warnings);
  }
  // Implausible inputs (a modulus in GPa read as Pa, ...): a UserWarning each, the values still computed.
  for (const auto& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();  // warnings as errors
  const Converter convert(result_form(precision, strings), precision);
  py::dict d;
  for (const auto& [name, value] : record)
    d[py::str(name)] = name == "shape" ? py::object(py::str(value)) : convert(value);
  return d;
}

// trace_rows as three arrays, phi, n and s: float64, or decimal strings (object arrays).
py::tuple trace_arrays(const std::vector<std::array<std::string, 3>>& rows, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  py::list columns;
  for (std::size_t c = 0; c < 3; ++c) {
    if (strings) {
      py::array out = py::module_::import("numpy").attr("empty")(n, "dtype"_a = "object");
      for (py::ssize_t i = 0; i < n; ++i) out[py::int_(i)] = py::str(rows[static_cast<std::size_t>(i)][c]);
      columns.append(out);
    } else {
      py::array_t<double> out(n);
      double* p = out.mutable_data();
      for (py::ssize_t i = 0; i < n; ++i) p[i] = read_decimal<double>(rows[static_cast<std::size_t>(i)][c]);
      columns.append(out);
    }
  }
  return py::tuple(columns);
}

// rig_trace_rows as six arrays, phi, n, s, lag, lag_rate (float64, or decimal strings) and mode (str).
py::tuple rig_trace_arrays(const std::vector<RigTraceRow>& rows, bool strings) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  const auto numpy = py::module_::import("numpy");
  py::list columns;
  const auto text_column = [&](auto field) {
    py::array out = numpy.attr("empty")(n, "dtype"_a = "object");
    for (py::ssize_t i = 0; i < n; ++i) out[py::int_(i)] = py::str(field(rows[static_cast<std::size_t>(i)]));
    columns.append(out);
  };
  const auto column = [&](auto field) {
    if (strings) return text_column(field);
    py::array_t<double> out(n);
    double* p = out.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) p[i] = read_decimal<double>(field(rows[static_cast<std::size_t>(i)]));
    columns.append(out);
  };
  column([](const RigTraceRow& r) -> const std::string& { return r.phi; });
  column([](const RigTraceRow& r) -> const std::string& { return r.n; });
  column([](const RigTraceRow& r) -> const std::string& { return r.s; });
  column([](const RigTraceRow& r) -> const std::string& { return r.lag; });
  column([](const RigTraceRow& r) -> const std::string& { return r.lag_rate; });
  text_column([](const RigTraceRow& r) -> const std::string& { return r.mode; });
  return py::tuple(columns);
}

// describe_normalisation as a dict: counts as int, decimal values as float (digits None), mpf or
// strings (digits D), descriptions ("none", "1 (uniform phases)", the column) as str.
py::dict normalisation_dict(const WaveSpec& spec, const py::object& digits_obj, bool strings) {
  const auto digits = optional_int(digits_obj, "digits");
  Precision p;
  p.type = NumberType::mpfr;
  p.digits = digits ? *digits : 17;
  std::vector<std::pair<std::string, std::string>> rows;
  {
    py::gil_scoped_release release;
    rows = describe_normalisation(spec, p.digits);
  }
  const Converter convert(strings ? Form::text : digits ? result_form(p, false) : Form::float64, p);
  py::dict d;
  for (const auto& [name, value] : rows) {
    if (!strings && (name == "samples" || name == "harmonics"))
      d[py::str(name)] = py::int_(std::stoull(value));
    else if (name == "column" || name == "time_column" || name == "end_point" || !is_decimal(value))
      d[py::str(name)] = py::str(value);
    else
      d[py::str(name)] = convert(value);
  }
  return d;
}

// The least-squares Fourier fit (fit.hpp) of samples given as arrays or as a samples Wave.
PyWave fit_wave(const py::object& y, const py::object& harmonics, const py::object& t) {
  WaveSpec samples;
  if (py::isinstance<PyWave>(y)) {
    if (!t.is_none()) throw InputError("t given with a Wave: the wave's own phases are fitted (expected t = None)");
    samples = y.cast<const PyWave&>().spec;
  } else {
    samples = samples_wave(array_texts(y, "y"), t.is_none() ? std::vector<std::string>() : array_texts(t, "t"), "samples");
  }
  const auto k = optional_int(harmonics, "harmonics");
  if (!k) throw py::type_error("harmonics = None: expected an integer K, 1 to " + std::to_string(max_fit_harmonics));
  if (*k < 0)  // 0 and above the limit: fit_fourier's message
    throw InputError("harmonics = " + std::to_string(*k) + ": expected 1 to " + std::to_string(max_fit_harmonics));
  PyWave out;
  {
    py::gil_scoped_release release;
    auto fit = std::make_shared<FourierFit>(fit_fourier(samples, static_cast<unsigned>(*k)));
    out.spec = fitted_wave(*fit, "fit");
    out.fit = std::move(fit);
  }
  out.fitted = samples.name;
  return out;
}

std::string wave_repr(const PyWave& w) {
  const WaveSpec& s = w.spec;
  if (w.fit)
    return "<vibrofric.Wave fit: " + std::to_string(w.fit->harmonics.empty() ? 0U : w.fit->harmonics.back().k) + " harmonics to " +
           std::to_string(w.fit->samples) + " samples, rms residual " + w.fit->rms_residual + ">";
  if (s.kind == WaveKind::samples)
    return "<vibrofric.Wave samples: " + std::to_string(s.samples.size()) + " values" +
           (s.times.empty() ? std::string("") : std::string(", time column")) + ">";
  if (s.kind == WaveKind::fourier) return "<vibrofric.Wave fourier: " + std::to_string(s.harmonics.size()) + " harmonics>";
  return "<vibrofric.Wave " + s.name + ">";
}

constexpr const char* physical_doc = R"doc(physical(wave, *, E1, nu1, E2, nu2, v0, f, A=None, mu0, u_mean=None, F_N=None, G1=None, G2=None, shape="flat", radius=None, R=None, half_angle=None, flat_radius=None, unit=None, mass=None, k_system=None, damping=None, digits=None, type=None, max_iterations=None, escalate=True, strings=False, nan_on_error=False) -> dict

The tool's `physical` from SI inputs: effective moduli and stiffnesses (Eq. 1), beta = G* v0 /
(mu0 E* A f) (Eq. 5), gamma = u_mean/A (Eq. 14) -- or gamma solving <F_N>(gamma) = F_N for a given
mean normal load -- then mu/mu0 (Eq. 15), mu, the mean forces, the peak load and contact
pressures, beta_c (Eq. 6) and the fractions of the period in contact and (flat punch) in stick.
Curved indenters by MDR (model.md).

E1, E2 Pa > 0; nu1, nu2 in (-1, 0.5]; G1, G2 Pa (default E/(2(1 + nu))); v0 m/s; f Hz; A m
(zero-to-peak), or for a samples wave unit ('m', 'mm', 'um', 'nm': its values' unit; A is then
half their peak-to-peak, returned as A_m); mu0 > 0; exactly one of u_mean (m, mean indentation) and F_N (N, mean load).
shape 'flat' (radius m), 'sphere' (R m), 'cone' (half_angle degrees), 'wearflat' (R, flat_radius m)
or 'profile:FILE' (heights in m). Numbers as for mu() (floats by their shortest decimal text).
mass kg and k_system N/m (both, flat punch; damping N s/m optional): rig dynamics (model.md), a body
of mass m on the apparatus' spring; then kappa, omega, zeta and the rig's stick, slip and flight
fractions and Floquet multiplier follow contact_fraction.

Returns a dict with exactly the tool's output names, in its order: shape, A_m (given unit),
E_star_Pa, G_star_Pa, k_z_N_per_m and k_x_N_per_m (flat) or contact_radius_max_m (curved), lambda
(wearflat), beta, gamma, u_mean_m (given F_N), mu_over_mu0, mu, F_N_mean_N, F_x_mean_N, at the
deepest instant F_N_peak_N, p_mean_peak_Pa and p_max_peak_Pa (Hertz on the sphere; inf where the
elastic pressure is unbounded: the punch's rim, the cone's tip, a profile's kink), beta_c (inf:
stick at every beta), contact_fraction (curved: the central spring's) and stick_fraction (curved: the
springs' stick shares averaged over the MDR half-row to the largest contact radius). Values as float (type None/'double': the
nearest double of the tool's --type double text), numpy.longdouble, or for digits=D mpmath.mpf /
decimal strings equal to `vibrofric physical --digits D --format json`; strings=True gives the
tool's strings for every type. ValueError with the library's message (naming the input by its keyword).

Any numeric input may be an array: the inputs broadcast (numpy's rules) and every output but shape
is an array of the broadcast shape (float64, longdouble, or object arrays of mpf / strings), each
element the scalar call's value. An element that fails raises its error prefixed with its index
('at index (2,): ...'), or with nan_on_error=True (scipy's convention) is NaN (None in object
arrays) while the others answer.
)doc";

constexpr const char* trace_doc = R"doc(trace(wave, beta, gamma, *, points=1000, digits=17, strings=False, kappa=None, omega=None, zeta=None, profile='flat') -> (phi, n, s), or with kappa and omega (phi, n, s, lag, lag_rate, mode)

The normal force n(phi) = max(0, gamma + w(phi)) and the tangential force s(phi) over one period
in the periodic steady state (Fig. 2 of the paper; Eqs. 7-11), flat punch, as the tool's `trace`:
points + 1 equally spaced phases 0, 1/points, ..., 1, both ends of every stick phase and the
contact boundaries (where n = s = 0 exactly), phi ascending. Each value to `digits` significant
digits (computed at digits plus guard digits); three float64 arrays, or arrays of decimal strings
with strings=True. points 2 to 1000000.

With kappa and omega (zeta optional), the rig's periodic state (model.md, "Rig dynamics"), as
`trace --kappa K --omega W --zeta Z`: six arrays (phi, n, s, lag, lag_rate, mode), the body's lag
Y = X - beta phi behind the drive and Y' in units of mu0 k_z A/k_x, and the mode ('stick', 'slip',
'backward', 'flight') as str; both ends of every span (two entries at one phi where a mode ends).

With a curved profile (as mu's profile=, the tool's `trace --profile P`): n and s summed over the
half-row of MDR springs, in the units of the row (mean(s)/mean(n) over the period is mu's value),
at the equally spaced phases and the central spring's contact boundaries.
)doc";

constexpr const char* fit_doc = R"doc(fit(y, harmonics, t=None) -> Wave

The least-squares trigonometric polynomial of degree K = harmonics through a sampled signal, as
the tool's `fit` (model.md, "Waveform catalogue"): y and t as for samples() (or y a samples Wave),
in the signal's units. Uniform phases (no t): the DFT, exact least squares, needs 2K < N. With
time stamps: Householder QR on the phases (t - t0)/T in mpfr, needs N >= 2K + 1 and a condition
number at most 1e12. Coefficients are written to 17 significant digits.

Returns the fitted Fourier wave (normalised like any fourier wave), usable wherever a wave is,
with .harmonics [(k, a_k, b_k)] (floats, k = 0 the mean), .method, .rms_residual and
.max_residual (of y_j - fit(phi_j), in y's units) and .fourier_text(), the fourier file the tool
writes (fourier:FILE reads it back to the same wave).
)doc";

}  // namespace

PYBIND11_MODULE(vibrofric, m) {
  py::options options;
  options.disable_function_signatures();  // each docstring opens with its Python signature
  m.doc() = R"doc(vibrofric: sliding friction under large-amplitude normal oscillation.

The contact-mechanical theory of M. Popov, "Friction under large-amplitude normal oscillations",
on the C++ library vibrofric: mu() is mu/mu0 (Eq. 15), psi() the reduction function Psi_w(beta)
(Eq. 12), physical() the same from SI inputs (Eqs. 1, 5, 14), trace() n and s over a period
(Fig. 2); wave() a wave by name, samples() / fourier() user waves from arrays, fit() a Fourier
series through samples, profile() a measured indenter, verify() the paper's claims. Results are
correctly rounded doubles, or exact decimals at any precision.
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

  py::class_<PyWave>(m, "Wave",
                     "A waveform: vibrofric.wave(text), or built from arrays by vibrofric.samples, vibrofric.fourier "
                     "or vibrofric.fit. Accepted wherever a wave name is.")
      .def_property_readonly("name", [](const PyWave& w) { return w.spec.name; })
      .def_property_readonly("kind", [](const PyWave& w) { return kind_name(w.spec.kind); },
                             "sine, triangle, sawtooth-right, sawtooth-left, square, power, fourier or samples")
      .def("__len__",
           [](const PyWave& w) {
             if (w.spec.kind == WaveKind::samples) return w.spec.samples.size();
             if (w.spec.kind == WaveKind::fourier) return w.spec.harmonics.size();
             throw py::type_error("a catalogue wave (" + w.spec.name + ") has no samples or harmonics");
           })
      .def_property_readonly(
          "harmonics",
          [](const PyWave& w) -> py::object {
            if (w.spec.kind != WaveKind::fourier) return py::none();
            py::list out;
            for (const auto& h : w.spec.harmonics)
              out.append(py::make_tuple(h.k, read_decimal<double>(h.a), read_decimal<double>(h.b)));
            return out;
          },
          "fourier waves: [(k, a_k, b_k)] as given or fitted (floats, the raw coefficients before the "
          "normalisation; k = 0 is the mean, when given); None for other waves")
      .def_property_readonly(
          "method", [](const PyWave& w) -> py::object { return w.fit ? py::object(py::str(w.fit->method)) : py::none(); },
          "fit(): how the coefficients were computed (DFT or least squares, with the digits); else None")
      .def_property_readonly(
          "rms_residual",
          [](const PyWave& w) -> py::object {
            return w.fit ? py::object(py::float_(read_decimal<double>(w.fit->rms_residual))) : py::none();
          },
          "fit(): root mean square of y_j - fit(phi_j) over the samples (3 digits, y's units); else None")
      .def_property_readonly(
          "max_residual",
          [](const PyWave& w) -> py::object {
            return w.fit ? py::object(py::float_(read_decimal<double>(w.fit->max_residual))) : py::none();
          },
          "fit(): largest |y_j - fit(phi_j)| (3 digits, y's units); else None")
      .def(
          "fourier_text",
          [](const PyWave& w, const py::object& source) {
            if (!w.fit) throw InputError("fourier_text() of '" + w.spec.name + "': only a Wave from vibrofric.fit has a fit to write");
            return fourier_file_text(*w.fit, source.is_none() ? w.fitted : scalar_text(source, "source"));
          },
          "source"_a = py::none(),
          R"doc(fourier_text(source=None) -> str

The fit as the fourier file the tool's `fit` writes ('#' comments: source -- default the fitted
wave's name --, method, K, N, residuals; then 'k a_k b_k' and one line per harmonic, 17 digits).
Written to a file, fourier:FILE is this wave. ValueError for a wave that is not a fit.
)doc")
      .def("normalisation", [](const PyWave& w, const py::object& digits, bool strings) {
             return normalisation_dict(w.spec, digits, strings);
           },
           "digits"_a = py::none(), "strings"_a = false,
           R"doc(normalisation(digits=None, strings=False) -> dict

The normalisation the wave went through (model.md, "Waveform catalogue": user waves have zero
mean and max w - min w = 2, w = (raw - offset)/scale), as the tool's --diagnostics. Samples:
samples, end_point, time_column, period, column, raw_mean, raw_min, raw_max, scale
(= (raw_max - raw_min)/2) and factor (= 1/scale). Fourier: harmonics, mean_removed,
peak_to_peak, scale, factor. Catalogue waves: {'normalisation': 'none (...)'}. Numbers as float
(17 digits), or to `digits` significant digits as mpmath.mpf / strings; descriptions as str.
)doc")
      .def("__repr__", wave_repr)
      .def(py::pickle(
          [](const PyWave& w) {
            const WaveSpec& s = w.spec;
            py::object fit = py::none();
            if (w.fit)
              fit = py::make_tuple(harmonic_list(w.fit->harmonics), w.fit->method, w.fit->rms_residual, w.fit->max_residual,
                                   w.fit->samples);
            return py::make_tuple(pickle_version, static_cast<int>(s.kind), s.name, s.exponent, harmonic_list(s.harmonics),
                                  text_list(s.samples), text_list(s.times), s.column, s.value_column, s.time_column,
                                  s.period_from_stamps, fit, w.fitted, s.periods_averaged);
          },
          [](const py::tuple& t) {
            check_state(t, 14, "Wave");
            PyWave w;
            WaveSpec& s = w.spec;
            s.kind = static_cast<WaveKind>(t[1].cast<int>());
            s.name = t[2].cast<std::string>();
            s.exponent = t[3].cast<std::string>();
            s.harmonics = harmonics_of(t[4]);
            s.samples = texts_of(t[5]);
            s.times = texts_of(t[6]);
            s.column = t[7].cast<std::string>();
            s.value_column = t[8].cast<std::string>();
            s.time_column = t[9].cast<std::string>();
            s.period_from_stamps = t[10].cast<std::string>();
            if (!t[11].is_none()) {
              const auto f = t[11].cast<py::tuple>();
              auto fit = std::make_shared<FourierFit>();
              fit->harmonics = harmonics_of(f[0]);
              fit->method = f[1].cast<std::string>();
              fit->rms_residual = f[2].cast<std::string>();
              fit->max_residual = f[3].cast<std::string>();
              fit->samples = f[4].cast<std::size_t>();
              w.fit = std::move(fit);
            }
            w.fitted = t[12].cast<std::string>();
            s.periods_averaged = t[13].cast<unsigned>();
            return w;
          }));
  py::class_<PyProfile>(m, "Profile", "A measured axisymmetric indenter profile built by vibrofric.profile.")
      .def_property_readonly("name", [](const PyProfile& p) { return p.spec.name; })
      .def("__len__", [](const PyProfile& p) { return p.spec.r.size(); })
      .def(py::pickle(
          [](const PyProfile& p) {
            const ProfileSpec& s = p.spec;
            // A computed parameter (physical's wear-flat lambda) never reaches a Profile object.
            if (s.parameter_value) throw InputError("profile " + s.name + ": a computed parameter cannot be pickled");
            return py::make_tuple(pickle_version, static_cast<int>(s.kind), s.name, s.parameter, text_list(s.r),
                                  text_list(s.f), s.height_unit);
          },
          [](const py::tuple& t) {
            check_state(t, 7, "Profile");
            PyProfile p;
            p.spec.kind = static_cast<ProfileKind>(t[1].cast<int>());
            p.spec.name = t[2].cast<std::string>();
            p.spec.parameter = t[3].cast<std::string>();
            p.spec.r = texts_of(t[4]);
            p.spec.f = texts_of(t[5]);
            p.spec.height_unit = t[6].cast<std::string>();
            return p;
          }))
      .def("__repr__", [](const PyProfile& p) {
        return "<vibrofric.Profile measured: " + std::to_string(p.spec.r.size()) + " samples>";
      });

  m.def(
      "samples",
      [](const py::object& y, const py::object& t, const py::object& periods) {
        const auto ys = array_texts(y, "y");
        const auto ts = t.is_none() ? std::vector<std::string>() : array_texts(t, "t");
        return PyWave{samples_wave(ys, ts, "samples", record_periods(periods)), nullptr, ""};
      },
      "y"_a, "t"_a = py::none(), py::kw_only(), "periods"_a = py::none(),
      R"doc(samples(y, t=None, *, periods=None) -> Wave

A sampled periodic signal, linear between the samples, normalised to zero mean and
max w - min w = 2 (model.md, "Waveform catalogue"). Without t: y_0 ... y_{N-1} at phi = j/N, one
period without its end point (N >= 2). With t: time stamps t_0 ... t_N, strictly increasing, and
y_N = y_0 (one period with its end point; t_N - t_0 is the period); or, as a DAQ records, no end
point and uniform stamps t_j = t_0 + j dt (then phi = j/N and the period is N dt). Exactly as the same numbers in a
samples:FILE (floats by their shortest decimal text; strings exact); ValueError for what such a
file would be refused for (NaN, ragged t and y, a constant signal, repeated periods). periods (the
tool's --periods): a record of K periods, averaged sample by sample (uniform phases, N a multiple
of K); None: one period, and a record that looks like several noisy periods is a ValueError saying
so; 1: one period, not checked.
)doc");
  m.def(
      "fourier",
      [](const py::object& a, const py::object& b, const py::object& a0) {
        const auto as = array_texts(a, "a");
        const auto bs = array_texts(b, "b");
        const std::string a0s = a0.is_none() ? std::string() : scalar_text(a0, "a0");
        if (!a0.is_none() && a0s.empty()) throw InputError("a0 is empty: expected a decimal number");
        return PyWave{fourier_wave(as, bs, a0s, "fourier"), nullptr, ""};
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
      "wave",
      [](const py::object& text, const py::object& column, const py::object& periods) {
        if (!py::isinstance<py::str>(text))
          throw py::type_error("wave = " + py_repr(text) + ": expected a name such as 'sine' or 'samples:FILE'");
        WaveReadOptions options;
        options.periods = record_periods(periods);
        if (!column.is_none()) {
          if (py::isinstance<py::str>(column))
            options.column = column.cast<std::string>();
          else if (const auto c = optional_int(column, "column"))
            options.column = std::to_string(*c);
        }
        return PyWave{parse_wave(text.cast<std::string>(), options), nullptr, ""};
      },
      "text"_a, py::kw_only(), "column"_a = py::none(), "periods"_a = py::none(),
      R"doc(wave(text, *, column=None, periods=None) -> Wave

A wave by name, as the tool's --wave: 'sine', 'triangle', 'sawtooth-right', 'sawtooth-left',
'square', 'power:P', 'fourier:FILE' or 'samples:FILE'. column (the tool's --column): the value
column of a samples file with a header, by its name or 1-based index (a column named 'time' or 't'
still gives the time stamps); the name becomes 'samples:FILE#COLUMN'. periods (the tool's
--periods): the periods a samples record holds, as in samples(). The file is read once, here.
)doc");

  m.def(
      "physical",
      [](const py::object& wave, const py::object& E1, const py::object& nu1, const py::object& E2,
         const py::object& nu2, const py::object& v0, const py::object& f, const py::object& A, const py::object& mu0,
         const py::object& u_mean, const py::object& F_N, const py::object& G1, const py::object& G2,
         const py::object& shape, const py::object& radius, const py::object& R, const py::object& half_angle,
         const py::object& flat_radius, const py::object& unit, const py::object& mass, const py::object& k_system,
         const py::object& damping, const py::object& digits, const py::object& type,
         const py::object& max_iterations, bool escalate, bool strings, bool nan_on_error) {
        const WaveSpec w = to_wave(wave);
        if (!unit.is_none() && !py::isinstance<py::str>(unit))
          throw py::type_error("unit = " + py_repr(unit) + ": expected 'm', 'mm', 'um' or 'nm'");
        const Precision precision = to_precision(optional_int(digits, "digits"), type);
        const BatchOptions options = solver_controls(max_iterations, escalate);
        if (!py::isinstance<py::str>(shape))
          throw py::type_error("shape = " + py_repr(shape) + ": expected 'flat', 'sphere', 'cone', 'wearflat' or 'profile:FILE'");
        // The keywords are the request's member names, which its messages use.
        const std::map<std::string, const py::object*> given{
            {"E1", &E1},   {"nu1", &nu1},       {"E2", &E2},   {"nu2", &nu2},   {"G1", &G1},
            {"G2", &G2},   {"v0", &v0},         {"f", &f},     {"A", &A},       {"u_mean", &u_mean},
            {"F_N", &F_N}, {"mu0", &mu0},       {"radius", &radius}, {"R", &R}, {"half_angle", &half_angle},
            {"flat_radius", &flat_radius}, {"mass", &mass}, {"k_system", &k_system}, {"damping", &damping}};
        auto request_of = [&](const std::map<std::string, py::object>& values) {
          PhysicalRequest request;
          request.shape.text = shape.cast<std::string>();
          if (!unit.is_none()) request.unit.text = unit.cast<std::string>();
          for (auto& [member, input] : request.inputs()) {
            const auto it = values.find(member);
            if (it != values.end()) input->text = scalar_text(it->second, member);
          }
          return request;
        };
        const py::module_ np = py::module_::import("numpy");
        std::vector<std::string> names;
        py::list arrays;
        bool broadcast = false;
        for (const auto& [name, value] : given)
          if (!value->is_none()) {
            names.push_back(name);
            arrays.append(*value);
            broadcast = broadcast || (!py::isinstance<py::str>(*value) && np.attr("ndim")(*value).cast<int>() > 0);
          }
        if (!broadcast) {
          std::map<std::string, py::object> values;
          for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = arrays[k];
          return py::object(physical_dict(w, request_of(values), precision, options, strings));
        }
        // Arrays broadcast against each other (numpy's rules) and the scalars: every output an
        // array of the broadcast shape (shape stays one string). A failing element is NaN (None
        // for strings) with nan_on_error, else its error names its index.
        const py::list parts = np.attr("broadcast_arrays")(*arrays);
        const py::tuple dims = parts[0].attr("shape");
        const std::size_t count = parts[0].attr("size").cast<std::size_t>();
        std::vector<std::optional<py::dict>> rows(count);
        for (std::size_t i = 0; i < count; ++i) {
          std::map<std::string, py::object> values;
          for (std::size_t k = 0; k < names.size(); ++k) values[names[k]] = parts[k].attr("flat")[py::int_(i)].attr("item")();
          const auto where = [&] { return "at index " + py::str(np.attr("unravel_index")(i, dims)).cast<std::string>() + ": "; };
          try {
            rows[i] = physical_dict(w, request_of(values), precision, options, strings);
          } catch (const InputError& e) {
            if (!nan_on_error) throw InputError(where() + e.what());
          } catch (const SolverError& e) {
            if (!nan_on_error) throw SolverError(where() + e.what());
          }
        }
        const auto first = std::find_if(rows.begin(), rows.end(), [](const auto& r) { return r.has_value(); });
        if (first == rows.end())
          throw InputError("physical: every element failed (nan_on_error = True): expected at least one to answer");
        py::dict out;
        const bool objects = strings || result_form(precision, strings) == Form::mpf;
        for (const auto& item : **first) {
          const py::str name = py::reinterpret_borrow<py::str>(item.first);
          if (name.cast<std::string>() == "shape") {
            out[name] = item.second;
            continue;
          }
          py::list column;
          for (const auto& r : rows)
            column.append(r ? py::object((*r)[name])
                            : objects ? py::object(py::none()) : py::object(py::float_(std::numeric_limits<double>::quiet_NaN())));
          const char* dtype = objects ? "object" : precision.type == NumberType::float80 ? "longdouble" : "float64";
          out[name] = np.attr("array")(column, "dtype"_a = dtype).attr("reshape")(dims);
        }
        return py::object(out);
      },
      "wave"_a, py::kw_only(), "E1"_a, "nu1"_a, "E2"_a, "nu2"_a, "v0"_a, "f"_a, "A"_a = py::none(), "mu0"_a,
      "u_mean"_a = py::none(), "F_N"_a = py::none(), "G1"_a = py::none(), "G2"_a = py::none(), "shape"_a = "flat",
      "radius"_a = py::none(), "R"_a = py::none(), "half_angle"_a = py::none(), "flat_radius"_a = py::none(),
      "unit"_a = py::none(), "mass"_a = py::none(), "k_system"_a = py::none(), "damping"_a = py::none(),
      "digits"_a = py::none(), "type"_a = py::none(), "max_iterations"_a = py::none(), "escalate"_a = true,
      "strings"_a = false, "nan_on_error"_a = false, physical_doc);

  m.def(
      "trace",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& points,
         const py::object& digits, bool strings, const py::object& kappa, const py::object& omega,
         const py::object& zeta, const py::object& profile) -> py::tuple {
        const WaveSpec w = to_wave(wave);
        TraceRequest request;
        request.profile = to_profile(profile);
        request.beta.text = scalar_text(beta, "beta");
        request.gamma.text = scalar_text(gamma, "gamma");
        if (const auto n = optional_int(points, "points")) request.points = *n;
        if (const auto d = optional_int(digits, "digits")) request.digits = *d;
        if (!kappa.is_none() || !omega.is_none() || !zeta.is_none()) {
          if (kappa.is_none() || omega.is_none())
            throw InputError(std::string("missing ") + (kappa.is_none() ? "kappa" : "omega") +
                             ": rig dynamics needs kappa and omega (zeta is optional)");
          RigSpec rig;
          rig.kappa = scalar_text(kappa, "kappa");
          rig.omega = scalar_text(omega, "omega");
          rig.zeta = zeta.is_none() ? std::string("0") : scalar_text(zeta, "zeta");
          std::vector<RigTraceRow> rows;
          {
            py::gil_scoped_release release;
            rows = rig_trace_rows(w, request, rig);
          }
          return rig_trace_arrays(rows, strings);
        }
        std::vector<std::array<std::string, 3>> rows;
        {
          py::gil_scoped_release release;
          rows = trace_rows(w, request);
        }
        return trace_arrays(rows, strings);
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "points"_a = 1000, "digits"_a = 17, "strings"_a = false,
      "kappa"_a = py::none(), "omega"_a = py::none(), "zeta"_a = py::none(), "profile"_a = "flat", trace_doc);

  m.def("fit", fit_wave, "y"_a, "harmonics"_a, "t"_a = py::none(), fit_doc);

  m.def(
      "mu",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& profile,
         const py::object& digits, const py::object& type, const py::object& threads, const py::object& max_iterations,
         bool escalate, bool strings, bool nan_on_error, bool certify, const py::object& kappa,
         const py::object& omega, const py::object& zeta) {
        Evaluation e;
        e.quantity = Quantity::mu;
        if (!kappa.is_none() || !omega.is_none() || !zeta.is_none()) {
          if (kappa.is_none() || omega.is_none())
            throw InputError(std::string("missing ") + (kappa.is_none() ? "kappa" : "omega") +
                             ": rig dynamics needs kappa and omega (zeta is optional)");
          if (certify) throw InputError("certify: certified values exist for the quasi-static model only, not with kappa/omega");
          if (!escalate) throw InputError("escalate=False: rig dynamics is always computed in mpfr at two precisions");
          e.rig.emplace();
          e.rig->kappa = scalar_text(kappa, "kappa");
          e.rig->omega = scalar_text(omega, "omega");
          e.rig->zeta = zeta.is_none() ? std::string("0") : scalar_text(zeta, "zeta");
          check_rig(*e.rig);
        }
        e.nan_on_error = nan_on_error;
        e.certify = certify;
        e.digits = optional_int(digits, "digits");
        e.type = type;
        e.profile = to_profile(profile);
        e.profile_text = py_repr(profile);
        if (e.rig && e.profile.kind != ProfileKind::flat)
          throw InputError("kappa/omega with profile = " + e.profile_text +
                           ": the springs of a curved contact share the body, so the MDR row does not decouple "
                           "(rig dynamics: the flat punch only)");
        e.threads = to_threads(threads);
        if (auto mi = optional_int(max_iterations, "max_iterations")) e.max_iterations = *mi;
        e.escalate = escalate;
        e.strings = strings;
        return evaluate_broadcast(wave, beta, gamma, e);
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "profile"_a = "flat", "digits"_a = py::none(),
      "type"_a = py::none(), "threads"_a = 0, "max_iterations"_a = py::none(), "escalate"_a = true,
      "strings"_a = false, "nan_on_error"_a = false, "certify"_a = false, "kappa"_a = py::none(),
      "omega"_a = py::none(), "zeta"_a = py::none(), mu_doc);

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
         const py::object& omega, const py::object& zeta, const py::object& digits, const py::object& type, bool strings) {
        const WaveSpec w = to_wave(wave);
        const Precision precision = to_precision(optional_int(digits, "digits"), type);
        RigSpec spec;
        spec.kappa = scalar_text(kappa, "kappa");
        spec.omega = scalar_text(omega, "omega");
        spec.zeta = zeta.is_none() ? std::string("0") : scalar_text(zeta, "zeta");
        const Point point{scalar_text(beta, "beta"), scalar_text(gamma, "gamma")};
        RigReport r;
        {
          py::gil_scoped_release release;
          r = evaluate_rig(w, point, spec, precision);
        }
        const Converter convert(result_form(precision, strings), precision);
        char floquet[32];
        std::snprintf(floquet, sizeof floquet, "%.6g", r.floquet);
        py::dict d;
        for (const auto& [name, value] : std::vector<std::pair<const char*, std::string>>{
                 {"mu_over_mu0", r.mu}, {"stick_fraction", r.stick_fraction}, {"slip_fraction", r.slip_fraction},
                 {"backward_slip_fraction", r.backward_fraction}, {"flight_fraction", r.flight_fraction},
                 {"amplitude", r.amplitude}, {"largest_backward_slip", r.largest_backward_slip},
                 {"floquet_multiplier", floquet}, {"relative_error_estimate", r.relative_error}})
          d[py::str(name)] = convert(value);
        return d;
      },
      "wave"_a, "beta"_a, "gamma"_a, py::kw_only(), "kappa"_a, "omega"_a, "zeta"_a = py::none(), "digits"_a = py::none(),
      "type"_a = py::none(), "strings"_a = false, R"doc(rig(wave, beta, gamma, *, kappa, omega, zeta=None, digits=None, type=None, strings=False) -> dict

Rig dynamics at one point (the tool's mu --kappa --omega --zeta; model.md, "Rig dynamics"): a body
of mass m on a system spring k_s (damper c), kappa = k_s/k_x, omega = sqrt(k_x/m)/(2 pi f),
zeta = c/(2 sqrt(m k_s)). Returns the tool's fields, in its order: mu_over_mu0 (as mu() would),
stick_fraction, slip_fraction, flight_fraction (they add to 1), backward_slip_fraction (the part of
slip_fraction slipping backward), amplitude (half the peak-to-peak of X - beta phi) and
largest_backward_slip (both in units of mu0 k_z A/k_x), floquet_multiplier (0: below what
difference quotients resolve) and relative_error_estimate (the two precisions apart). Values as
mu(): float for type None/'double', or decimal strings with strings=True; the fractions carry
the digits the two precisions agree on. ValueError for bad input, vibrofric.SolverError where no
periodic state is found.
)doc");

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

  // A call that fits no signature (a misspelt or missing keyword, an extra argument) is one line
  // naming what is wrong, as the tool's flags, not pybind11's listing of the overloads: each
  // function is wrapped, and its parameters are read from its docstring's first line.
  m.def("_did_you_mean", [](const std::string& typed, const std::vector<std::string>& known) { return did_you_mean(typed, known); });
  py::exec(R"py(
import functools as _functools
import re as _re


def _one_line_calls(name):
    f = globals()[name]
    head = _re.match(r"\w+\((.*?)\)", f.__doc__ or "")
    params = [p.strip().lstrip("*").split("=")[0] for p in head.group(1).split(",")] if head else []
    params = [p for p in params if p]
    required = [p.strip() for p in head.group(1).split(",") if "=" not in p and p.strip() not in ("*", "")] if head else []

    @_functools.wraps(f)
    def call(*args, **kwargs):
        try:
            return f(*args, **kwargs)
        except TypeError as e:
            if "incompatible function arguments" not in str(e):
                raise
            for k in kwargs:
                if k not in params:
                    hint = _did_you_mean(k, params)
                    raise TypeError("%s() got an unexpected keyword argument '%s': expected %s%s"
                                    % (name, k, ", ".join(params), "; " + hint if hint else "")) from None
            given = set(required[:len(args)]) | set(kwargs)
            missing = [p for p in required if p not in given]
            if missing:
                raise TypeError("%s() missing %s: %s" % (name, "argument" if len(missing) == 1 else "arguments",
                                                         ", ".join(missing))) from None
            raise TypeError("%s() takes %s (%d positional given)" % (name, head.group(1) if head else "other arguments",
                                                                     len(args))) from None
    globals()[name] = call


for _name in ("samples", "fourier", "profile", "wave", "physical", "trace", "fit", "mu", "psi", "rig", "verify"):
    _one_line_calls(_name)
del _name
)py", m.attr("__dict__"));

  m.attr("catalogue") = py::cast(catalogue_names());
  py::list keys;
  for (const auto& c : claims_catalogue()) keys.append(c.key);
  m.attr("claims") = keys;
}
