// The CIE 1931 2° colour matching functions from Debian's colord-data (installed by
// scripts/install-deps.sh): 360–830 nm in 5 nm steps, interpolated linearly to 1 nm. Read
// by scripts/make_wavelength_table.cpp and by the tests that check spectral code against
// them; both skip or fail with the path when the file is missing.
#pragma once

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace vkpt::internal::cie {

inline const char* const kCmfPath = "/usr/share/colord/cmf/CIE1931-2deg-XYZ.cmf";
constexpr int kFirstNm = 360, kLastNm = 830;

struct Cmf {
  std::vector<double> x, y, z;  // at kFirstNm + i nm
  double yIntegral = 0.0;       // ∫ ȳ dλ in nm, summed at 1 nm
};

// Empty if the file is missing or not the table it should be.
inline Cmf LoadCmf() {
  std::ifstream in(kCmfPath);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t begin = text.find("BEGIN_DATA\n"), end = text.find("END_DATA", begin + 1);
  Cmf cmf;
  if (begin == std::string::npos || end == std::string::npos) return cmf;
  std::istringstream data(text.substr(begin + 11, end - begin - 11));
  constexpr int kBands = (kLastNm - kFirstNm) / 5 + 1;
  std::vector<double> rows[3];
  for (std::vector<double>& row : rows)
    for (int i = 0; i < kBands; ++i) data >> row.emplace_back();
  if (!data) return cmf;
  for (int nm = kFirstNm; nm <= kLastNm; ++nm) {
    const int i = std::min((nm - kFirstNm) / 5, kBands - 2);
    const double t = (nm - kFirstNm - 5 * i) / 5.0;
    cmf.x.push_back(rows[0][i] * (1 - t) + rows[0][i + 1] * t);
    cmf.y.push_back(rows[1][i] * (1 - t) + rows[1][i + 1] * t);
    cmf.z.push_back(rows[2][i] * (1 - t) + rows[2][i + 1] * t);
    cmf.yIntegral += cmf.y.back();
  }
  return cmf;
}

}  // namespace vkpt::internal::cie
