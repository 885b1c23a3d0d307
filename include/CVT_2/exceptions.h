// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The exceptions the library throws on bad input: what is wrong and where.
#ifndef CVT_2_EXCEPTIONS_H
#define CVT_2_EXCEPTIONS_H

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Thrown when the input does not describe a valid domain or valid generators: a point outside
/// the domain, a NaN or infinite coordinate, constraints that cross, an empty domain. The message
/// gives the coordinates; `index()` gives the position of the offending item in the input range
/// (or `no_index`), so that a reader can turn it into a file line.
class Domain_error : public std::invalid_argument {
 public:
  /// `index()` when the error concerns no single input item
  static constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();
  /// an error described by `what`, about the input item at `index`
  explicit Domain_error(const std::string& what, std::size_t index = no_index)
      : std::invalid_argument(what), m_index(index) {}
  std::size_t index() const { return m_index; }  ///< the offending item, or `no_index`

 private:
  std::size_t m_index;
};

namespace IO {

/// \ingroup PkgCvt2IO
/// Thrown by the readers on malformed input; the message reads `file:line: what (near 'token')`,
/// or `file: what` when no line applies (line 0).
class Parse_error : public std::invalid_argument {
 public:
  /// an error described by `what` at `line` of `file`, near `token`
  Parse_error(const std::string& file, std::size_t line, const std::string& what,
              const std::string& token = {})
      : std::invalid_argument(file + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                              ": " + what +
                              (token.empty() ? std::string() : " (near '" + token + "')")),
        m_file(file),
        m_line(line),
        m_token(token) {}
  const std::string& file() const { return m_file; }    ///< the file
  std::size_t line() const { return m_line; }           ///< the line, from 1 (0: none)
  const std::string& token() const { return m_token; }  ///< the token, printable, shortened

 private:
  std::string m_file;
  std::size_t m_line;
  std::string m_token;
};

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_EXCEPTIONS_H
