// Shared pieces of the Python module: the Wave and Profile objects, Python arguments to the
// library's decimal texts and its results back to Python, and the binders module.cpp calls.
#pragma once
// stl.h and numpy.h here: every file of the module sees the same type casters.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <charconv>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "vibrofric/api/arrays.hpp"
#include "vibrofric/api/catalogue.hpp"
#include "vibrofric/api/exact_input.hpp"
#include "vibrofric/api/evaluate.hpp"
#include "vibrofric/api/inplane.hpp"
#include "vibrofric/api/profile_spec.hpp"

namespace vibrofric::python {

namespace py = pybind11;
using namespace pybind11::literals;

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

std::string py_repr(const py::handle& x);
// An exact rational as Python's fractions.Fraction (certify=True's values).
py::object to_fraction(const exact::Rational& x);

WaveSpec to_wave(const py::object& w);
// The in-plane drive of the keywords longitudinal (None: 0), transverse, phase and in_plane_wave
// (None: their defaults), checked as the tool's flags (check_inplane).
InPlaneSpec inplane_spec(bool constant, const py::object& longitudinal, const py::object& transverse,
                         const py::object& phase, const py::object& in_plane_wave);
ProfileSpec to_profile(const py::object& p);

// The decimal text of one Python number or string: floats by their shortest round-trip text (0.1
// is the decimal 0.1, as typed on the tool's command line), integers exactly, strings as given
// (exact decimals at any precision). Booleans and other types are refused.
std::string scalar_text(const py::handle& x, const std::string& what);
// scalar_text read by the one grammar (InputError naming `what`).
InputValue scalar_value(const py::handle& x, const std::string& what);

std::optional<int> optional_int(const py::object& x, const char* what);

Precision to_precision(const std::optional<int>& digits, const py::object& type);

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

Form result_form(const Precision& p, bool strings);

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

// The binders, in the order module.cpp calls them.
void bind_errors(py::module_& m);        // common.cpp: vibrofric.SolverError, error translation
void bind_classes(py::module_& m);       // bind_classes.cpp: Wave, Profile
void bind_waves(py::module_& m);         // bind_waves.cpp: samples, fourier, profile, wave
void bind_physical(py::module_& m);      // bind_physical.cpp: physical
void bind_trace(py::module_& m);         // bind_trace.cpp: trace
void bind_fit(py::module_& m);           // bind_waves.cpp: fit
void bind_values(py::module_& m);        // bind_values.cpp: mu, psi, rig
void bind_verify(py::module_& m);        // bind_verify.cpp: verify
void bind_one_line_calls(py::module_& m);  // bind_calls.cpp: one-line errors for bad calls
void bind_catalogues(py::module_& m);    // bind_verify.cpp: catalogue, claims

}  // namespace vibrofric::python
