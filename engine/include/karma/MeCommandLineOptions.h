/* MeCommandLineOptions.h: a command line that its readers can consume.
 *
 * A program copies its arguments once, then passes the copy to each reader
 * in turn (the viewer through RRenderContextCreate, then the application):
 *
 *   MeCommandLineOptions *opts = MeCommandLineOptionsCreate(argc, argv);
 *   rc = RRenderContextCreate(opts, 0, 1);      (the viewer eats its options)
 *   if (MeCommandLineOptionsGetInt(opts, "-bodies", &n, 1)) ...
 *   MeCommandLineOptionsDestroy(opts);
 *
 * Every look-up takes an `eat` flag. With eat TRUE, the option it matched
 * (and the value after it, for the value look-ups) is removed from the list,
 * so readers further down never see it; with eat FALSE the list is left as
 * it was. Eating happens whether or not the value parsed: the option has
 * been dealt with (and a warning given).
 *
 * Matching is exact and case-sensitive; element 0, the program name, is
 * never matched. When an option appears more than once, a look-up finds
 * the first occurrence and eats only that one, so a loop collects them all:
 *
 *   while ((dir = MeCommandLineOptionsGetString(opts, "-I", 1)) != NULL) ...
 *
 * The value of an option is simply the next argument, whatever it looks
 * like ("-5" is a value, not an option).
 *
 * Ownership: the options own copies of all argument strings, in one block
 * from MeMemoryAPI. Strings handed out stay valid until Destroy, even after
 * they have been eaten. A NULL options pointer reads as an empty command
 * line (RRenderContextCreate receives NULL override options, for example). */
#ifndef KARMA_MECOMMANDLINEOPTIONS_H
#define KARMA_MECOMMANDLINEOPTIONS_H

#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MeCommandLineOptions {
  int m_argc;          /* arguments left, program name included (>= 1) */
  const char **m_argv; /* m_argv[0..m_argc-1], then NULL; read-only */
} MeCommandLineOptions;

/* Copies argc arguments (argv[0] is the program name). NULL argv or argc < 0
 * warns and yields options holding only an empty program name; NULL entries
 * become empty strings. Returns NULL only if memory runs out. */
MEPUBLIC MeCommandLineOptions *MEAPI MeCommandLineOptionsCreate(int argc, const char *argv[]);

/* Splits `commandLine` at white space into arguments, the first being the
 * program name. Double quotes group text containing spaces ("a b" gives one
 * argument a b, "" an empty one); inside or outside quotes, \" stands for a
 * literal quote. A missing closing quote warns and ends the argument at the
 * end of the string. NULL reads as "". Returns NULL only if memory runs
 * out. */
MEPUBLIC MeCommandLineOptions *MEAPI MeCommandLineOptionsCreateFromString(const char *commandLine);

/* Frees the options and all their strings. NULL is accepted. */
MEPUBLIC void MEAPI MeCommandLineOptionsDestroy(MeCommandLineOptions *options);

/* TRUE if `name` is present. */
MEPUBLIC MeBool MEAPI MeCommandLineOptionsCheckFor(MeCommandLineOptions *options, const char *name, MeBool eat);

/* Of the `count` names listed, returns the index (into `names`) of the one
 * that appears earliest on the command line, or -1 if none does. Eating
 * removes just that occurrence. */
MEPUBLIC int MEAPI MeCommandLineOptionsCheckForList(MeCommandLineOptions *options, const char *const *names, int count,
                                                    MeBool eat);

/* The argument after `name`, or NULL if `name` is absent or is the last
 * argument (that case warns, and eating removes the lone flag). */
MEPUBLIC const char *MEAPI MeCommandLineOptionsGetString(MeCommandLineOptions *options, const char *name, MeBool eat);

/* Reads the value after `name` as a number into *value. Returns TRUE on
 * success. Returns FALSE leaving *value untouched when the option is absent
 * (silently) or its value is missing, does not parse completely ("12x"),
 * is out of range, or (for floats) is not finite (each with a warning
 * naming the option and the text). */
MEPUBLIC MeBool MEAPI MeCommandLineOptionsGetFloat(MeCommandLineOptions *options, const char *name, MeReal *value,
                                                   MeBool eat);
MEPUBLIC MeBool MEAPI MeCommandLineOptionsGetInt(MeCommandLineOptions *options, const char *name, int *value,
                                                 MeBool eat);

/* Number of arguments left, program name included (0 for NULL options). */
MEPUBLIC int MEAPI MeCommandLineOptionsGetCount(const MeCommandLineOptions *options);

/* Argument i (0 = program name), or NULL if i is out of range. */
MEPUBLIC const char *MEAPI MeCommandLineOptionsGetArg(const MeCommandLineOptions *options, int i);

ME_EXTERN_C_END

#endif /* KARMA_MECOMMANDLINEOPTIONS_H */
