// Binds the classes vibrofric.Wave and vibrofric.Profile: their properties, fourier_text(),
// normalisation(), repr and pickling.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/fit.hpp"

namespace vibrofric::python {

namespace {

// Pickle states (Wave and Profile cross to other processes: multiprocessing, concurrent.futures,
// Dask): every field as written, so a wave read from a file needs no file where it is unpickled,
// and the wave unpickled is the same wave, value for value. The first item is the state's version.
py::list text_list(const std::vector<Decimal>& v) {
  py::list out;
  for (const auto& x : v) out.append(x.text());
  return out;
}
std::vector<std::string> texts_of(const py::handle& l) { return l.cast<std::vector<std::string>>(); }
// A state's decimal, read as any input is ("" for none).
Decimal decimal_of(const std::string& text, const std::string& what) {
  return text.empty() ? Decimal() : *InputValue::read(text, "unpickled " + what).decimal();
}
std::vector<Decimal> decimals_of(const py::handle& l, const std::string& what) {
  std::vector<Decimal> out;
  for (const std::string& t : texts_of(l)) out.push_back(decimal_of(t, what));
  return out;
}
py::list harmonic_list(const std::vector<WaveSpec::Harmonic>& hs) {
  py::list out;
  for (const auto& h : hs) out.append(py::make_tuple(h.k, h.a.text(), h.b.text()));
  return out;
}
std::vector<WaveSpec::Harmonic> harmonics_of(const py::handle& l) {
  std::vector<WaveSpec::Harmonic> out;
  for (const auto& h : l.cast<py::list>()) {
    const auto t = h.cast<py::tuple>();
    out.push_back({t[0].cast<unsigned>(), decimal_of(t[1].cast<std::string>(), "a_k"), decimal_of(t[2].cast<std::string>(), "b_k")});
  }
  return out;
}
constexpr int pickle_version = 1;
void check_state(const py::tuple& t, std::size_t size, const char* what) {
  if (t.size() != size || t[0].cast<int>() != pickle_version)
    throw InputError(std::string("unpickling a ") + what + ": a state of " + std::to_string(t.size()) +
                     " items, expected version " + std::to_string(pickle_version) + " with " + std::to_string(size));
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

}  // namespace

void bind_classes(py::module_& m) {
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
              out.append(py::make_tuple(h.k, h.a.to<double>(), h.b.to<double>()));
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
            return py::make_tuple(pickle_version, static_cast<int>(s.kind), s.name, s.exponent.text(),
                                  harmonic_list(s.harmonics), text_list(s.samples), text_list(s.times), s.column,
                                  s.value_column, s.time_column,
                                  s.period_from_stamps ? s.period_from_stamps->text() : std::string(), fit, w.fitted,
                                  s.periods_averaged);
          },
          [](const py::tuple& t) {
            check_state(t, 14, "Wave");
            PyWave w;
            WaveSpec& s = w.spec;
            s.kind = static_cast<WaveKind>(t[1].cast<int>());
            s.name = t[2].cast<std::string>();
            s.exponent = decimal_of(t[3].cast<std::string>(), "exponent");
            s.harmonics = harmonics_of(t[4]);
            s.samples = decimals_of(t[5], "sample");
            s.times = decimals_of(t[6], "time");
            s.column = t[7].cast<std::string>();
            s.value_column = t[8].cast<std::string>();
            s.time_column = t[9].cast<std::string>();
            if (const auto period = t[10].cast<std::string>(); !period.empty()) s.period_from_stamps = decimal_of(period, "period");
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
            if (s.parameter.computed_value() || s.height_unit.computed_value())
              throw InputError("profile " + s.name + ": a computed parameter cannot be pickled");
            const auto texts = [](const std::vector<Decimal>& v) {
              py::list out;
              for (const Decimal& d : v) out.append(d.text());
              return out;
            };
            return py::make_tuple(pickle_version, static_cast<int>(s.kind), s.name, s.parameter.text(), texts(s.r),
                                  texts(s.f), s.height_unit.given() ? s.height_unit.text() : std::string("1"));
          },
          [](const py::tuple& t) {
            check_state(t, 7, "Profile");
            PyProfile p;
            p.spec.kind = static_cast<ProfileKind>(t[1].cast<int>());
            p.spec.name = t[2].cast<std::string>();
            const auto number = [](const std::string& text, const char* what) {
              return text.empty() ? InputValue() : InputValue::read(text, std::string("pickled Profile ") + what);
            };
            const auto decimals = [&](const py::handle& list, const char* what) {
              std::vector<Decimal> out;
              for (const std::string& text : texts_of(list)) out.push_back(*number(text, what).decimal());
              return out;
            };
            p.spec.parameter = number(t[3].cast<std::string>(), "parameter");
            p.spec.r = decimals(t[4], "r");
            p.spec.f = decimals(t[5], "f");
            const std::string unit = t[6].cast<std::string>();
            if (unit != "1") p.spec.height_unit = number(unit, "height unit");
            return p;
          }))
      .def("__repr__", [](const PyProfile& p) {
        return "<vibrofric.Profile measured: " + std::to_string(p.spec.r.size()) + " samples>";
      });
}

}  // namespace vibrofric::python
