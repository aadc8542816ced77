#include "text.hpp"

#include <array>
#include <cstdio>
#include <optional>
#include <utility>

#include "vibrofric/api/catalogue.hpp"

namespace vibrofric::detail {

namespace {

// The code point of the UTF-8 sequence at s[i] and its length; none where it is ill-formed.
std::optional<std::pair<char32_t, std::size_t>> code_point_at(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return std::make_pair(char32_t(b0), std::size_t(1));
  std::size_t n = 0;
  char32_t cp = 0, least = 0;
  if ((b0 & 0xE0) == 0xC0) { n = 2; cp = b0 & 0x1F; least = 0x80; }
  else if ((b0 & 0xF0) == 0xE0) { n = 3; cp = b0 & 0x0F; least = 0x800; }
  else if ((b0 & 0xF8) == 0xF0) { n = 4; cp = b0 & 0x07; least = 0x10000; }
  else return std::nullopt;
  if (i + n > s.size()) return std::nullopt;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return std::nullopt;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  if (cp < least || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return std::nullopt;
  return std::make_pair(cp, n);
}

// Characters a reader cannot see or tell from a plain space or nothing: C0 and C1 controls, DEL,
// the no-break and other spaces, the soft hyphen, zero-width and direction marks, the BOM.
bool invisible(char32_t c) {
  return c < 0x20 || (c >= 0x7F && c <= 0xA0) || c == 0xAD || (c >= 0x2000 && c <= 0x200F) ||
         (c >= 0x2028 && c <= 0x202F) || (c >= 0x205F && c <= 0x2064) || c == 0x3000 || c == 0xFEFF;
}

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace

bool is_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto cp = code_point_at(s, i);
    if (!cp) return false;
    i += cp->second;
  }
  return true;
}

std::string utf8_from_cp1252(const std::string& s) {
  // 0x80–0x9F of Windows-1252; 0 where it defines none (read as Latin-1's C1 control).
  static constexpr std::array<char16_t, 32> high{
      0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
      0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
      0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};
  std::string out;
  out.reserve(s.size() + s.size() / 4);
  for (const char ch : s) {
    const auto b = static_cast<unsigned char>(ch);
    const char32_t c = b >= 0x80 && b < 0xA0 && high[b - 0x80] ? high[b - 0x80] : b;
    append_utf8(out, c);
  }
  return out;
}

std::string as_utf8(const std::string& s) { return is_utf8(s) ? s : utf8_from_cp1252(s); }

std::string visible(const std::string& s) {
  std::string out;
  const auto escape = [&](std::size_t i, std::size_t n) {
    for (std::size_t k = i; k < i + n; ++k) {
      const auto u = static_cast<unsigned char>(s[k]);
      char b[8];
      std::snprintf(b, sizeof b, u == '\r' ? "\\r" : u == '\t' ? "\\t" : "\\x%02X", u);
      out += b;
    }
  };
  for (std::size_t i = 0; i < s.size();) {
    const auto cp = code_point_at(s, i);
    if (!cp) {
      escape(i, 1);
      ++i;
      continue;
    }
    if (invisible(cp->first))
      escape(i, cp->second);
    else
      out.append(s, i, cp->second);
    i += cp->second;
  }
  return out;
}

}  // namespace vibrofric::detail
