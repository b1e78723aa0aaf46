// Measured complex indices of refraction of four metals, sampled at the wavelengths the three
// colour channels stand for: 650 nm (red), 550 nm (green) and 450 nm (blue).
//
// Sources: gold, silver and copper from P. B. Johnson and R. W. Christy, "Optical constants of
// the noble metals", Phys. Rev. B 6, 4370 (1972); aluminium as in A. D. Rakic, "Algorithm for
// the determination of intrinsic optical constants of metal films: application to aluminum",
// Appl. Opt. 34, 4755 (1995). The numbers were read off the tabulated spectra pbrt-v4 ships
// (its gold, silver and copper tables are Johnson & Christy's on their photon-energy grid; its
// aluminium table agrees with Rakic's, n 0.96 and k 6.69 at 550 nm) and linearly interpolated
// to the three wavelengths. Normal-incidence reflectance ((n-1)^2 + k^2) / ((n+1)^2 + k^2) from them:
//
//   metal      650 nm  550 nm  450 nm
//   gold       0.940   0.848   0.386
//   silver     0.970   0.960   0.918
//   copper     0.941   0.634   0.553
//   aluminium  0.912   0.921   0.924
//
// (tests/render/bsdf_test.cpp checks these against the published reflectance of each metal.)

#include <array>
#include <string_view>

#include "raylab/scene/metals.h"

namespace raylab {

namespace {

struct NamedMetal {
  std::string_view name;
  ConductorIor ior;
};

//                                  n at 650, 550, 450 nm         k at 650, 550, 450 nm
constexpr std::array kMetals{
    NamedMetal{"gold", kGoldIor},
    NamedMetal{"silver", {{0.1394f, 0.1248f, 0.1517f}, {4.1288f, 3.3396f, 2.4704f}}},
    NamedMetal{"copper", {{0.2166f, 0.9582f, 1.1658f}, {3.6377f, 2.5771f, 2.3939f}}},
    NamedMetal{"aluminium", {{1.4748f, 0.9586f, 0.6180f}, {7.7941f, 6.6870f, 5.4694f}}},
};

}  // namespace

std::optional<ConductorIor> metal_ior(std::string_view name) {
  if (name == "aluminum") name = "aluminium";  // the American spelling
  for (const NamedMetal& m : kMetals) {
    if (m.name == name) return m.ior;
  }
  return std::nullopt;
}

}  // namespace raylab
