/* program.h: a complete program of the guide (file scope): only the C
 * library headers the guide leaves out (exit, atexit). Karma's headers are
 * the program's own #includes. */
#include <stdlib.h>
