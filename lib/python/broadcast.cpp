// The batch evaluation behind vibrofric.mu and vibrofric.psi (broadcast.hpp): the arguments as
// columns, numpy's broadcasting, the result array filled as the values arrive, certify=True.
#include "broadcast.hpp"

#include <array>
#include <cstdint>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrofric/api/certify.hpp"

namespace vibrofric::python {

namespace {

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

// The batch's result: a scalar for scalar arguments (float for float64), else the array in the
// broadcast's shape.
py::object shaped(const Output& out, const Converter& convert, const std::vector<std::size_t>& dims, const py::tuple& shape) {
  const py::array& flat = out.array();
  if (dims.empty()) {
    if (convert.form() == Form::float64) return py::float_(static_cast<const double*>(flat.data())[0]);
    return flat[py::int_(0)];
  }
  return flat.attr("reshape")(shape);
}

// certify=True (certify.hpp): each point computed as without it, and proven the correct rounding
// of its exact value (piecewise-linear waves, flat punch); the result is (lo, hi) of
// fractions.Fraction, equal, the exact value (arrays of them for array arguments).
py::object certify_broadcast(const WaveSpec& wave, const Precision& precision, const BatchOptions& options,
                             const Column& betas, const Column& gammas, const BroadcastIndex& index, std::size_t n,
                             const std::vector<std::size_t>& dims, const py::tuple& shape, const Evaluation& e) {
  std::optional<Certifier> certifier;
  if (options.profile.kind != ProfileKind::flat && (options.rig || options.inplane))
    throw InputError("certify=True with profile = " + e.profile_text + (options.rig ? " and a rig" : " and an in-plane drive") +
                     ": certified values exist for the flat punch only (a curved contact integrates over springs)");
  if (e.nan_on_error)
    throw InputError("certify=True gives exact values or raises, nan_on_error=True gives NaN for a failure: give one of them");
  if (!options.escalate)
    throw InputError("certify=True proves the guaranteed value, escalate=False gives one that is not guaranteed: give one of them");
  // An in-plane drive: the longitudinal drive's exact values (certify_inplane), point by point.
  const std::optional<InPlaneSpec>& inplane = options.inplane;
  try {
    if (inplane) check_certifiable(wave, *inplane);
    else if (options.rig) rig_wave_input(wave);  // a proven rig state, point by point
    else certifier.emplace(wave, options.profile);
  } catch (const InputError& err) {
    if (options.profile.kind != ProfileKind::flat)
      throw InputError("certify=True with profile = " + e.profile_text + ": " + err.what());
    throw InputError(std::string("certify=True: ") + err.what());
  }
  const bool with_gamma = e.quantity == Quantity::mu && !(inplane && inplane->constant_normal);
  auto point = [&](std::size_t i) {
    const auto at = index(i);
    return Point{InputValue::read(betas.text(at[0]), "beta"),
                 with_gamma ? InputValue::read(gammas.text(at[1]), "gamma") : InputValue()};
  };
  std::vector<std::pair<exact::Rational, exact::Rational>> values(n);
  {
    py::gil_scoped_release release;
    evaluate_stream(wave, e.quantity, n, point, precision, options, [&](std::size_t i, const StreamValue& value) {
      if (value.error) rethrow_at_index(dims, i, value.error);
      Certificate c;
      try {
        c = inplane         ? certify_inplane(wave, point(i), *inplane, precision, value.text).mu
            : options.rig ? certify_rig(wave, point(i), *options.rig, precision, value.text, options.profile).mu
                            : (*certifier)(e.quantity, point(i), precision, value.text);
      } catch (const InputError& err) {
        rethrow_at_index(dims, i, std::make_exception_ptr(InputError(std::string("certify=True: ") + err.what())));
      }
      if (!c.correctly_rounded)
        rethrow_at_index(dims, i, std::make_exception_ptr(SolverError(
            "certify=True: the value " + value.text + " is not the correct rounding of the exact value " +
            (c.exact.empty() ? "[" + c.lower_text + ", " + c.upper_text + "]" : c.exact) +
            " (that is " + c.nearest.front() + "): a solver bug, please report it")));
      values[i] = {c.lower, c.upper};
    });
  }
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

// The result at the broadcast of beta, gamma, kappa, omega and zeta (rig dynamics with one of the
// rig's parameters an array): the points grouped by their rig, one evaluate_stream per group.
py::object rig_broadcast(const WaveSpec& wave, const Precision& precision, BatchOptions options, const py::object& beta,
                         const py::object& gamma, const Evaluation& e) {
  const py::module_ np = py::module_::import("numpy");
  const auto& [kappa, omega, zeta] = *e.rig_arrays;
  const py::tuple arrays = np.attr("broadcast_arrays")(beta, gamma, kappa, omega, zeta.is_none() ? py::object(py::int_(0)) : zeta);
  const py::tuple shape = py::array(arrays[0]).attr("shape");
  std::vector<std::size_t> dims;
  std::size_t n = 1;
  for (const auto& d : shape) {
    dims.push_back(d.cast<std::size_t>());
    n *= dims.back();
  }
  const char* names[] = {"beta", "gamma", "kappa", "omega", "zeta"};
  std::vector<Column> columns;
  for (int k = 0; k < 5; ++k) columns.emplace_back(np.attr("ravel")(arrays[k]).cast<py::array>(), names[k]);
  std::map<std::array<std::string, 3>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < n; ++i) groups[{columns[2].text(i), columns[3].text(i), columns[4].text(i)}].push_back(i);
  std::vector<std::pair<RigSpec, const std::vector<std::size_t>*>> rigs;
  for (const auto& [texts, members] : groups) {
    RigSpec spec;
    try {
      spec.kappa = InputValue::read(texts[0], "kappa");
      spec.omega = InputValue::read(texts[1], "omega");
      spec.zeta = InputValue::read(texts[2], "zeta");
      check_rig(spec);
    } catch (...) {
      rethrow_at_index(dims, members.front(), std::current_exception());
    }
    rigs.emplace_back(std::move(spec), &members);
  }
  options.deliver_errors = true;
  const Converter convert(result_form(precision, e.strings), precision);
  Output out(convert, n, dims, e.nan_on_error);
  {
    py::gil_scoped_release release;
    for (const auto& [spec, members] : rigs) {
      options.rig = spec;
      const auto& m = *members;
      evaluate_stream(
          wave, e.quantity, m.size(),
          [&](std::size_t j) {
            return Point{InputValue::read(columns[0].text(m[j]), "beta"), InputValue::read(columns[1].text(m[j]), "gamma")};
          },
          precision, options, [&](std::size_t j, const StreamValue& value) { out.put(m[j], value); });
    }
    out.flush();
  }
  return shaped(out, convert, dims, shape);
}

}  // namespace

py::object evaluate_broadcast(const py::object& wave_obj, const py::object& beta, const py::object& gamma,
                              const Evaluation& e) {
  const py::module_ np = py::module_::import("numpy");
  const bool constant = e.inplane && e.inplane->constant_normal;
  WaveSpec wave;
  if (constant)
    wave.name = "constant";  // n = 1: the in-plane solver reads no wave
  else
    wave = to_wave(wave_obj);
  const Precision precision = to_precision(e.digits, e.type);
  BatchOptions options;
  options.profile = e.profile;
  options.threads = e.threads;
  options.escalate = e.escalate;
  options.rig = e.rig;
  options.inplane = e.inplane;
  if (e.max_iterations) {
    if (*e.max_iterations < 1 || *e.max_iterations > root_iterations_limit)
      throw InputError("max_iterations = " + std::to_string(*e.max_iterations) + ": expected 1 to " +
                       std::to_string(root_iterations_limit));
    options.solver.max_root_iterations = static_cast<std::uintmax_t>(*e.max_iterations);
  }

  const bool with_gamma = e.quantity == Quantity::mu && !constant;
  if (constant && !gamma.is_none())
    throw InputError("gamma = " + py_repr(gamma) + " with wave 'constant': the normal force is constant (give gamma=None)");
  if (e.rig_arrays) return rig_broadcast(wave, precision, options, beta, gamma, e);
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
          return Point{InputValue::read(betas.text(at[0]), "beta"),
                       with_gamma ? InputValue::read(gammas.text(at[1]), "gamma") : InputValue()};
        },
        precision, options, [&](std::size_t i, const StreamValue& value) { out.put(i, value); });
    out.flush();
  }
  return shaped(out, convert, dims, shape);
}

}  // namespace vibrofric::python
