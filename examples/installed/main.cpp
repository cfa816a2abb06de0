// The README's C++ example as a program built against an installed corlab (make install or the
// .deb), with find_package(corlab) (CMakeLists.txt here) or pkg-config:
//   g++ -std=c++20 main.cpp $(pkg-config --cflags --libs corlab-cxx) -o readme_example
// Prints e(2.5 m/s) of corlab2026 for alumina on aluminium, e at three speeds and the data
// directory the library read its materials from.
//
// Sample run (installed in /usr/local; the .deb gives /usr/share/corlab):
//   $ ./readme_example
//   e(2.5 m/s) = 0.66834077552767601
//   e(0.5 m/s) = 0.85094889709869437
//   e(5 m/s) = 0.59062932012251634
//   e(10 m/s) = 0.51448185910629163
//   data directory: /usr/local/share/corlab
// SPDX-License-Identifier: BSD-3-Clause
#include <array>
#include <cstdio>
#include <exception>

#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

int main() {
  try {
    const std::array<double, 3> speeds = {0.5, 5.0, 10.0};  // [m/s]
    std::array<double, 3> restitutions{};                   // [-]
    // --- the README's example ---
    const auto& db = corlab::MaterialDatabase::builtin();
    const auto model = corlab::restitution::make_model("corlab2026", db.get("alumina_ma2023"),
                                                       db.get("aluminium_ma2023"));
    double e = model.cor(2.5);        // impact speed [m/s] -> e [-]
    model.cor(speeds, restitutions);  // vectorised over std::span, no allocation
    // --- end ---
    std::printf("e(2.5 m/s) = %.17g\n", e);
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      std::printf("e(%g m/s) = %.17g\n", speeds[i], restitutions[i]);
    }
    std::printf("data directory: %s\n", corlab::data_directory().c_str());
  } catch (const std::exception& err) {
    std::fprintf(stderr, "error: %s\n", err.what());
    return 2;
  }
  return 0;
}
