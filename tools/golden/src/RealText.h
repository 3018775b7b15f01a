/* RealText.h (internal): exact, locale-independent text for state values.
 *
 * FormatReal prints the shortest decimal that parses back to the same value of
 * the given precision; ParseReal parses it in that precision (so a single file
 * is parsed with float rounding, never double-then-float). Round trip:
 *   ParseReal(FormatReal(v, p), p) == v, bit for bit, for every v of precision p
 *   (NaN payloads aside: every NaN prints as "nan" or "-nan"). */
#ifndef KARMA_GOLDEN_SRC_REALTEXT_H
#define KARMA_GOLDEN_SRC_REALTEXT_H

#include <karma/golden/Precision.h>

#include <optional>
#include <string>
#include <string_view>

namespace karma::golden::detail {

std::string FormatReal(double value, Precision precision);
/* The whole of `text` must be the number; nullopt otherwise. */
std::optional<double> ParseReal(std::string_view text, Precision precision) noexcept;

/* Rounds to the precision (identity for Double). */
inline double RoundTo(double value, Precision precision) noexcept {
  return precision == Precision::Single ? static_cast<double>(static_cast<float>(value)) : value;
}

}  // namespace karma::golden::detail

#endif
