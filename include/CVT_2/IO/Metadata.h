// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Metadata: what made a file, written by the mesh writers in their headers.
#ifndef CVT_2_IO_METADATA_H
#define CVT_2_IO_METADATA_H

#include <CVT_2/IO/internal/write_number.h>

#include <algorithm>
#include <charconv>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Key-value pairs of plain text that `write_geojson()`, `write_vtu()` and `write_disv()` put in
/// their files' headers: what made the file (a program and version, the domain, the boundary's
/// mode and cell size). GeoJSON: a `"metadata"` object of strings beside `"features"`; VTU: an
/// XML comment `<!-- key: value -->` a pair (readers skip comments); DISV: a comment line
/// `# key: value` a pair.
using Metadata = std::vector<std::pair<std::string, std::string>>;

/// Raises the number under `key` to `value` where it is smaller: a bound that only grows, as
/// `max_deviation` once the boundary slid. A missing key is left missing.
inline void raise_metadata_number(Metadata& metadata, const std::string& key, double value) {
  for (auto& [k, v] : metadata) {
    if (k != key) continue;
    double was = 0;  // read in any locale; a value that is no number is replaced
    const auto r = std::from_chars(v.data(), v.data() + v.size(), was);
    v = internal::number_text(r.ec == std::errc() ? std::max(was, value) : value);
  }
}

}  // namespace IO

namespace internal {

// `s` as a JSON string, quotes and control characters escaped.
inline void write_json_string(std::ostream& os, const std::string& s) {
  os << '"';
  for (const char c : s) {
    if (c == '"' || c == '\\')
      os << '\\' << c;
    else if (static_cast<unsigned char>(c) < 0x20)
      os << "\\u00"
         << "0123456789abcdef"[(c >> 4) & 0xf] << "0123456789abcdef"[c & 0xf];
    else
      os << c;
  }
  os << '"';
}

// `s` on one line, with no "--" (which would end an XML comment): for comments.
inline std::string comment_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const char d = (c == '\n' || c == '\r') ? ' ' : c;
    if (d == '-' && !out.empty() && out.back() == '-') continue;
    out += d;
  }
  return out;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_IO_METADATA_H
