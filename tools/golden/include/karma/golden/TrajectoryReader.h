/* TrajectoryReader.h: reading trajectory files (format in TrajectoryWriter.h).
 *
 * The reader is strict about structure and exact about numbers: any deviation
 * from the format throws TrajectoryFormatError naming the source and line.
 * Numbers are parsed in the file's precision, so a file written by
 * TrajectoryWriter reads back bit for bit.
 *
 * The recorded hash lines are kept as they are (Trajectory::frames[i].hash and
 * finalHash) and are NOT required to match the values: a file edited by hand
 * still reads, and comparisons report the inconsistency. Use HashTrajectory()
 * to recompute. */
#ifndef KARMA_GOLDEN_TRAJECTORYREADER_H
#define KARMA_GOLDEN_TRAJECTORYREADER_H

#include <karma/golden/Error.h>
#include <karma/golden/Trajectory.h>

#include <filesystem>
#include <iosfwd>
#include <string>

namespace karma::golden {

/* `sourceName` is used in error messages only. */
MEPUBLIC Trajectory ReadTrajectory(std::istream &in, const std::string &sourceName);
/* Throws TrajectoryFormatError (line 0) if the file cannot be opened. */
MEPUBLIC Trajectory ReadTrajectoryFile(const std::filesystem::path &path);

}  // namespace karma::golden

#endif
