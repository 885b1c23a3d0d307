// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// A line-by-line tokenizer for the text readers: '#' comments, numbers checked in full.
#ifndef CVT_2_IO_INTERNAL_LINE_READER_H
#define CVT_2_IO_INTERNAL_LINE_READER_H

#include <CVT_2/exceptions.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace CVT_2 {
namespace internal {

// The file opened for reading, or a Parse_error that says it could not be.
inline std::ifstream open_input(const std::string& filename) {
  std::ifstream is(filename);
  if (!is) throw IO::Parse_error(filename, 0, "cannot open the file");
  return is;
}

class Line_reader {
 public:
  Line_reader(std::istream& is, std::string source) : m_is(is), m_source(std::move(source)) {}

  // The tokens of the next line that has any, or false at the end of the input.
  bool next(std::vector<std::string>& tokens) {
    std::string line;
    while (std::getline(m_is, line)) {
      ++m_line;
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos) line.erase(hash);
      std::istringstream ls(line);
      tokens.clear();
      for (std::string t; ls >> t;) tokens.push_back(t);
      if (!tokens.empty()) return true;
    }
    if (m_is.bad()) fail("read error");
    return false;
  }
  // Like next(), but the end of the input is an error that says what was expected.
  void expect(std::vector<std::string>& tokens, const std::string& what) {
    if (!next(tokens))
      throw IO::Parse_error(m_source, m_line, "unexpected end of file, expected " + what);
  }

  double real(const std::string& t) const {
    const char* b = t.c_str();
    char* e = nullptr;
    errno = 0;
    const double x = std::strtod(b, &e);
    // The whole token: a NUL byte inside it would otherwise end it early ("1\0junk" read as 1).
    if (e == b || e != b + t.size()) fail("not a number", t);
    if (!std::isfinite(x) || (errno == ERANGE && std::fabs(x) > 1))
      fail("number not finite or too large", t);
    return x;
  }
  long long integer(const std::string& t) const {
    const char* b = t.c_str();
    char* e = nullptr;
    errno = 0;
    const long long x = std::strtoll(b, &e, 10);
    if (e == b || e != b + t.size() || errno == ERANGE) fail("not an integer", t);
    return x;
  }
  std::size_t count(const std::string& t, const std::string& what) const {
    const long long n = integer(t);
    if (n < 0) fail("negative " + what, t);
    return static_cast<std::size_t>(n);
  }

  // The token is quoted in the message: printable characters only, and not too many.
  [[noreturn]] void fail(const std::string& what, const std::string& token = {}) const {
    std::string shown;
    for (const char c : token.substr(0, 40))
      shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (token.size() > 40) shown += "...";
    throw IO::Parse_error(m_source, m_line, what, shown);
  }
  std::size_t line() const { return m_line; }
  const std::string& source() const { return m_source; }

 private:
  std::istream& m_is;
  std::string m_source;
  std::size_t m_line = 0;
};

// For each point equal to an earlier one: its line and the line of the first one there, in
// file order. The triangulation merges them; the readers report them so that programs can say so.
template <class Point_2>
std::vector<std::array<std::size_t, 2>> repeated_points(const std::vector<Point_2>& points,
                                                        const std::vector<std::size_t>& lines) {
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
  std::vector<std::array<std::size_t, 2>> repeated;
  for (std::size_t k = 1, first = 0; k < order.size(); ++k) {
    if (points[order[k]] != points[order[first]])
      first = k;
    else
      repeated.push_back({lines[order[k]], lines[order[first]]});
  }
  std::sort(repeated.begin(), repeated.end());
  return repeated;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_IO_INTERNAL_LINE_READER_H
