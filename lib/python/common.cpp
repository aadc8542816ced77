// The shared pieces declared in common.hpp, and vibrofric.SolverError with the translation of the
// library's errors to Python exceptions.
#include "common.hpp"

#include <exception>
#include <string>

#include "vibrofric/api/suggest.hpp"

namespace vibrofric::python {

std::string py_repr(const py::handle& x) { return py::repr(x).cast<std::string>(); }

py::object to_fraction(const exact::Rational& x) {
  const py::object fraction = py::module_::import("fractions").attr("Fraction");
  const py::object integer = py::module_::import("builtins").attr("int");
  return fraction(integer(numerator(x).str()), integer(denominator(x).str()));
}

WaveSpec to_wave(const py::object& w) {
  if (py::isinstance<py::str>(w)) return parse_wave(w.cast<std::string>());
  if (py::isinstance<PyWave>(w)) return w.cast<const PyWave&>().spec;
  throw py::type_error("wave = " + py_repr(w) +
                       ": expected a name such as 'sine', 'power:3', 'samples:FILE', or a Wave from "
                       "vibrofric.samples / vibrofric.fourier");
}

InPlaneSpec inplane_spec(bool constant, const py::object& longitudinal, const py::object& transverse,
                         const py::object& phase, const py::object& in_plane_wave) {
  InPlaneSpec spec;
  spec.constant_normal = constant;
  spec.longitudinal = longitudinal.is_none() ? InputValue(*Decimal::read("0")) : scalar_value(longitudinal, "longitudinal");
  if (!transverse.is_none()) spec.transverse = scalar_value(transverse, "transverse");
  if (!phase.is_none()) spec.phase = scalar_value(phase, "phase");
  if (!in_plane_wave.is_none()) spec.wave = to_wave(in_plane_wave);
  check_inplane(spec);
  return spec;
}

ProfileSpec to_profile(const py::object& p) {
  if (py::isinstance<py::str>(p)) return parse_profile(p.cast<std::string>());
  if (py::isinstance<PyProfile>(p)) return p.cast<const PyProfile&>().spec;
  throw py::type_error("profile = " + py_repr(p) +
                       ": expected a name such as 'flat', 'sphere', 'wearflat:0.5', or a Profile from vibrofric.profile");
}

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

InputValue scalar_value(const py::handle& x, const std::string& what) { return InputValue::read(scalar_text(x, what), what); }

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

std::optional<int> optional_int(const py::object& x, const char* what) {
  if (x.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(x) || !(py::isinstance<py::int_>(x) || py::hasattr(x, "__index__")))
    throw py::type_error(std::string(what) + " = " + py_repr(x) + ": expected an integer");
  const long long v = py::int_(x).cast<long long>();
  if (v < -1000000000LL || v > 1000000000LL)
    throw InputError(std::string(what) + " = " + std::to_string(v) + ": out of range");
  return static_cast<int>(v);
}

void bind_errors(py::module_& m) {
  static py::exception<SolverError> solver_error(m, "SolverError", PyExc_ArithmeticError);
  solver_error.doc() =
      "The solver did not converge (a root finder or quadrature over its budget, or a precision that "
      "cannot resolve the problem without escalation). A subclass of ArithmeticError.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const MissingFileError& e) {
      PyErr_SetString(PyExc_FileNotFoundError, e.what());
    } catch (const InputError& e) {  // DomainError too
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SolverError& e) {  // PrecisionError too
      PyErr_SetString(solver_error.ptr(), e.what());
    }
  });
}

}  // namespace vibrofric::python
