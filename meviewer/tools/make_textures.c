/* make_textures: writes the textures MeViewer's programs name, as 24-bit
 * Windows BMP files, into the directory given:
 *
 *   checkerboard.bmp  128x128, 8x8 squares of 16 pixels, light grey (224)
 *                     and dark grey (64), the square at the top-left light.
 *
 *   usage: karma-make-textures DIR
 *
 * The build runs it into <build>/share/karma; the install copies the files
 * to <prefix>/share/karma. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { kSize = 128, kSquare = 16 };

static void Put16(unsigned char *p, unsigned v) { p[0] = (unsigned char)v, p[1] = (unsigned char)(v >> 8); }
static void Put32(unsigned char *p, uint32_t v) {
  Put16(p, v & 0xffffu);
  Put16(p + 2, v >> 16);
}

/* BMP: 14-byte file header, 40-byte info header, rows bottom first, each
 * kSize * 3 bytes (a multiple of 4: no padding) of B, G, R. */
static int WriteCheckerboard(const char *path) {
  unsigned char header[54];
  const uint32_t rowBytes = kSize * 3, pixelBytes = rowBytes * kSize;
  FILE *f = fopen(path, "wb");
  int y, x, ok;
  if (!f) return 0;
  memset(header, 0, sizeof header);
  header[0] = 'B', header[1] = 'M';
  Put32(header + 2, 54 + pixelBytes);
  Put32(header + 10, 54);
  Put32(header + 14, 40);
  Put32(header + 18, kSize);
  Put32(header + 22, kSize);
  Put16(header + 26, 1);
  Put16(header + 28, 24);
  Put32(header + 34, pixelBytes);
  Put32(header + 38, 2835); /* 72 dpi */
  Put32(header + 42, 2835);
  ok = fwrite(header, 1, sizeof header, f) == sizeof header;
  for (y = kSize - 1; y >= 0 && ok; --y) { /* file rows bottom first */
    unsigned char row[kSize * 3];
    for (x = 0; x < kSize; ++x) {
      const int light = ((x / kSquare) + (y / kSquare)) % 2 == 0;
      row[3 * x] = row[3 * x + 1] = row[3 * x + 2] = (unsigned char)(light ? 224 : 64);
    }
    ok = fwrite(row, 1, sizeof row, f) == sizeof row;
  }
  return fclose(f) == 0 && ok;
}

int main(int argc, char **argv) {
  char path[4096];
  if (argc != 2) {
    fprintf(stderr, "usage: karma-make-textures DIR\n");
    return 2;
  }
  snprintf(path, sizeof path, "%s/checkerboard.bmp", argv[1]);
  if (!WriteCheckerboard(path)) {
    fprintf(stderr, "karma-make-textures: cannot write %s\n", path);
    return 1;
  }
  return 0;
}
