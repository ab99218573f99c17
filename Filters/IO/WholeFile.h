// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file WholeFile.h
 * @brief Writing a file so that it is whole or not there: never a partial file, and an
 * existing file untouched when a write fails.
 *
 * The bytes go to a new file beside the target (".<name>.<pid>.<n>.part", in the same folder
 * so that the last step is a rename within one file system); every write, the flush, the sync
 * to the disk and the close are checked; on success the new file replaces the target in one
 * rename, and takes the target's permissions if it existed (else 0666 less the umask, as any
 * new file). A symbolic link is written through (the file it names is replaced); a hard link
 * to the target is left with the old file. The folder must be writable. On any failure the new file is removed and the reason given, one line, with the
 * system's words (for example "No space left on device").
 */
#ifndef MeshSimplification_WholeFile_h
#define MeshSimplification_WholeFile_h

#include <cstdio>
#include <functional>
#include <string>

namespace meshsimp
{

/// Calls write on a stream to a new file beside path, then replaces path with it; false with
/// the reason in error when write returns false or any step fails.
bool WriteWholeFile(
  const std::string& path, const std::function<bool(std::FILE*)>& write, std::string& error);

} // namespace meshsimp

#endif
