// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Example_arguments: the examples' positional arguments, each with a default, read strictly.
#ifndef CVT_2_EXAMPLES_EXAMPLE_ARGUMENTS_H
#define CVT_2_EXAMPLES_EXAMPLE_ARGUMENTS_H

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

// The arguments after the program's name. `-h` or `--help` prints `usage` (the example's first
// comment line) and exits; another argument that starts with '-' and is no number, or one too
// many, is an error, and so is a count or a number that does not read whole: each error names
// the argument and the value, and ends with the usage.
class Example_arguments {
 public:
  Example_arguments(int argc, char* argv[], std::string usage, std::size_t most)
      : m_args(argv + 1, argv + argc), m_usage(std::move(usage)) {
    // (after the program's name: argv[0])
    for (const std::string& a : m_args)
      if (a == "-h" || a == "--help") {
        std::cout << "usage: " << m_usage << '\n';
        std::exit(EXIT_SUCCESS);
      } else if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))) {
        fail("unknown option '" + a + "'");
      }
    if (m_args.size() > most) fail("too many arguments");
  }

  // Argument i (from 0), or `fallback` if there are fewer.
  std::string text(std::size_t i, const std::string& fallback) const {
    return i < m_args.size() ? m_args[i] : fallback;
  }
  // A whole number of at least `least`.
  std::size_t count(std::size_t i, const char* name, std::size_t fallback,
                    std::size_t least = 1) const {
    if (i >= m_args.size()) return fallback;
    const std::string& a = m_args[i];
    std::size_t end = 0;
    unsigned long long n = 0;
    try {
      if (!a.empty() && a[0] != '-') n = std::stoull(a, &end);  // stoull takes "-1"
    } catch (const std::exception&) {
      end = 0;
    }
    if (end == 0 || end != a.size() || n < least)
      fail(std::string(name) + " must be a whole number of at least " + std::to_string(least) +
           ", not '" + a + "'");
    return std::size_t(n);
  }
  // A finite number.
  double real(std::size_t i, const char* name, double fallback) const {
    if (i >= m_args.size()) return fallback;
    const std::string& a = m_args[i];
    std::size_t end = 0;
    double x = 0;
    try {
      x = std::stod(a, &end);
    } catch (const std::exception&) {
      end = 0;
    }
    if (end == 0 || end != a.size() || !std::isfinite(x))
      fail(std::string(name) + " must be a number, not '" + a + "'");
    return x;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(what + "\nusage: " + m_usage);
  }

  std::vector<std::string> m_args;
  std::string m_usage;
};

#endif  // CVT_2_EXAMPLES_EXAMPLE_ARGUMENTS_H
