// Binds vibrofric.trace: n and s over one period (flat punch, rig dynamics or a curved profile).
#include <array>
#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/commands.hpp"
#include "vibrofric/api/rig.hpp"

namespace vibrofric::python {

namespace {

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

}  // namespace

void bind_trace(py::module_& m) {
  static constexpr const char* trace_doc = R"doc(trace(wave, beta, gamma, *, points=1000, digits=17, strings=False, kappa=None, omega=None, zeta=None, profile='flat') -> (phi, n, s), or with kappa and omega (phi, n, s, lag, lag_rate, mode)

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
  m.def(
      "trace",
      [](const py::object& wave, const py::object& beta, const py::object& gamma, const py::object& points,
         const py::object& digits, bool strings, const py::object& kappa, const py::object& omega,
         const py::object& zeta, const py::object& profile) -> py::tuple {
        const WaveSpec w = to_wave(wave);
        TraceRequest request;
        request.profile = to_profile(profile);
        request.beta.value = scalar_value(beta, "beta");
        request.gamma.value = scalar_value(gamma, "gamma");
        if (const auto n = optional_int(points, "points")) request.points = *n;
        if (const auto d = optional_int(digits, "digits")) request.digits = *d;
        if (!kappa.is_none() || !omega.is_none() || !zeta.is_none()) {
          if (kappa.is_none() || omega.is_none())
            throw InputError(std::string("missing ") + (kappa.is_none() ? "kappa" : "omega") +
                             ": rig dynamics needs kappa and omega (zeta is optional)");
          RigSpec rig;
          rig.kappa = scalar_value(kappa, "kappa");
          rig.omega = scalar_value(omega, "omega");
          if (!zeta.is_none()) rig.zeta = scalar_value(zeta, "zeta");
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
}

}  // namespace vibrofric::python
