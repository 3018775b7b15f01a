/* Precision.h: which floating-point type a trajectory's values have.
 *
 * A trajectory records the precision of the build that wrote it ("single" =
 * MeReal is float, "double" = MeReal is double). The toolkit itself can read,
 * hash and compare files of either precision whatever its own build is: values
 * are held as double, which represents every float exactly. */
#ifndef KARMA_GOLDEN_PRECISION_H
#define KARMA_GOLDEN_PRECISION_H

#include <karma/MePrecision.h>

#include <optional>
#include <string_view>

namespace karma::golden {

enum class Precision { Single, Double };

/* The precision of MeReal in this build (from the generated MeConfig.h). */
inline constexpr Precision kBuildPrecision = KARMA_DOUBLE ? Precision::Double : Precision::Single;

/* "single" or "double": the spelling used in trajectory headers and golden keys. */
constexpr std::string_view PrecisionName(Precision p) noexcept { return p == Precision::Single ? "single" : "double"; }

constexpr std::optional<Precision> ParsePrecision(std::string_view name) noexcept {
  if (name == "single") return Precision::Single;
  if (name == "double") return Precision::Double;
  return std::nullopt;
}

}  // namespace karma::golden

#endif
