#include <karma/golden/GoldenKey.h>

#include <karma/golden/Error.h>

#include <cstdio>

namespace karma::golden {

namespace {

void ValidatePart(const std::string &value, const char *what) {
  bool ok = !value.empty() && value != "." && value != "..";
  for (unsigned char c : value)
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
                c == '.');
  if (!ok)
    throw GoldenError(std::string("invalid golden key ") + what + " '" + value +
                      "': use letters, digits, '_', '-' and '.' only");
}

}  // namespace

std::string FrameFileName(long frame) {
  char name[48];
  std::snprintf(name, sizeof name, "frame_%05ld.png", frame);
  return name;
}

void GoldenKey::Validate() const {
  ValidatePart(program, "program");
  ValidatePart(step, "step");
  ValidatePart(backend, "backend");
}

std::filesystem::path GoldenKey::RelativeDirectory() const {
  Validate();
  return std::filesystem::path(program) / step / (backend + "-" + std::string(PrecisionName(precision)));
}

}  // namespace karma::golden
