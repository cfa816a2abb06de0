// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reader for the NIST StRD transcriptions in data/nist/*.dat (test support).
//   "# certified <name> <value> [sd <value>]" lines, then rows "y x".
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace corlab::test {

struct NistProblem {
  std::vector<double> y;
  std::vector<double> x;
  std::map<std::string, double> certified;            ///< value per name
  std::map<std::string, double> certified_sd;         ///< standard deviation per parameter
  std::map<std::string, std::vector<double>> starts;  ///< "start1" -> values
};

inline NistProblem read_nist(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file);
  NistProblem p;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string first;
    if (!(ss >> first)) continue;
    if (first == "#") {
      std::string kind;
      ss >> kind;
      if (kind == "certified") {
        std::string name;
        double value = 0;
        ss >> name >> value;
        p.certified[name] = value;
        std::string sd;
        if (ss >> sd && sd == "sd") ss >> p.certified_sd[name];
      } else if (kind.rfind("start", 0) == 0) {
        std::string name;
        double value = 0;
        while (ss >> name >> value) p.starts[kind].push_back(value);
      }
      continue;
    }
    p.y.push_back(std::stod(first));
    double x = 0;
    ss >> x;
    p.x.push_back(x);
  }
  return p;
}

/// Number of agreeing significant digits, -log10(|a - b| / |b|) (LRE of McCullough 1998).
inline double significant_digits(double a, double b) {
  const double rel = std::abs(a - b) / std::abs(b);
  return rel == 0 ? 16.0 : -std::log10(rel);
}

}  // namespace corlab::test
