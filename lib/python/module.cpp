// The Python module `vibrofric` (pybind11): the library's evaluation, waves from arrays and the
// claims catalogue, for numpy users. μ̄/μ0 (Eq. 15) and Ψ_w(β) (Eq. 12) broadcast over β and γ like
// a scipy.special function; each batch is one call of the library's batch API, with the GIL
// released and the library's worker threads. Bad input is ValueError with the library's one-line
// message, a solver failure vibrofric.SolverError (an ArithmeticError); never NaN for a failure.
// One binder a command in bind_*.cpp (shared pieces in common.hpp), called here in the order of
// registration.
#include <pybind11/pybind11.h>

#include "common.hpp"

using namespace vibrofric::python;

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

  // The error translation first; the classes before the functions that take and return them; the
  // one-line call errors after every function they wrap.
  bind_errors(m);
  bind_classes(m);
  bind_waves(m);
  bind_physical(m);
  bind_trace(m);
  bind_fit(m);
  bind_values(m);
  bind_verify(m);
  bind_one_line_calls(m);
  bind_catalogues(m);
}
