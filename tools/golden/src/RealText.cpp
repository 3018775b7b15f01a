#include "RealText.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace karma::golden::detail {

std::string FormatReal(double value, Precision precision) {
  char buffer[64];
  std::to_chars_result r;
  if (std::isnan(value)) /* to_chars would print the payload-free "nan"/"-nan" anyway */
    return std::signbit(value) ? "-nan" : "nan";
  if (precision == Precision::Single)
    r = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
  else
    r = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, r.ptr);
}

std::optional<double> ParseReal(std::string_view text, Precision precision) noexcept {
  if (text.empty()) return std::nullopt;
  const char *first = text.data();
  const char *last = text.data() + text.size();
  /* from_chars rejects a leading '+', which the writer never prints; accept it
   * anyway for hand-written files. */
  if (*first == '+' && text.size() > 1 && first[1] != '-') ++first;
  if (precision == Precision::Single) {
    float f = 0.0f;
    auto [ptr, ec] = std::from_chars(first, last, f);
    if (ec != std::errc() || ptr != last) return std::nullopt;
    return static_cast<double>(f);
  }
  double d = 0.0;
  auto [ptr, ec] = std::from_chars(first, last, d);
  if (ec != std::errc() || ptr != last) return std::nullopt;
  return d;
}

}  // namespace karma::golden::detail
