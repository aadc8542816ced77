// fit: a samples file fitted by K harmonics, written as a fourier file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "vibrofric/api/fit.hpp"

namespace vibrofric::tool {

// A samples file fitted by K harmonics (DFT for uniform phases, least squares for time stamps),
// written as a fourier file that --wave fourier:FILE reads.
int run_fit(const Flags& f) {
  const WaveSpec wave = read_wave(f);
  if (!f.harmonics) throw InputError("missing --harmonics for 'fit'");
  const int harmonics = *f.harmonics;
  const FourierFit fit = fit_fourier(wave, static_cast<unsigned>(harmonics));
  const std::string text = fourier_file_text(fit, *f.wave);
  if (!f.output) {
    std::cout << text;
    return 0;
  }
  const std::string& path = *f.output;
  if (std::filesystem::is_directory(path))
    throw InputError("--output '" + detail::visible(path) + "' is a directory: expected a file name");
  std::ofstream out(path);
  if (!(out << text) || !(out.close(), out))
    throw InputError("--output '" + detail::visible(path) + "': cannot write the file");
  std::cerr << "fit: K = " << harmonics << " harmonics (" << fit.method << "), rms residual "
            << fit.rms_residual << ", written to " << path << '\n';
  return 0;
}

}  // namespace vibrofric::tool
