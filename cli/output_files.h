// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// optimize_seams' outputs: each path is checked before the (possibly long)
// run, and each file is written to a temporary file beside it and renamed
// over the target, so that a failed write never leaves a truncated file.

#ifndef SMSO_CLI_OUTPUT_FILES_H
#define SMSO_CLI_OUTPUT_FILES_H

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace optimize_seams_cli {

namespace internal {

inline std::filesystem::path directory_of(const std::string& path)
{
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  return dir.empty() ? std::filesystem::path(".") : dir;
}

// Creates an empty temporary file beside `path`, with the permissions a new
// file would get (or those of the existing target). Empty on failure, with
// errno set.
inline std::string make_temporary_beside(const std::string& path)
{
  const std::filesystem::path p(path);
  std::string name = (directory_of(path) / ("." + p.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  const int fd = ::mkstemp(buf.data());
  if(fd < 0)
    return std::string();
  struct stat st;
  mode_t mode;
  if(::stat(path.c_str(), &st) == 0)
    mode = st.st_mode & 07777;
  else
  {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if(::fchmod(fd, mode) != 0) {}   // the default 0600 is still a valid file
  ::close(fd);
  return std::string(buf.data());
}

// The file a write to `path` lands in: through a symbolic link, its target
// (renaming over the link would replace the link).
inline std::string resolved_target(const std::string& path)
{
  std::error_code ec;
  if(std::filesystem::is_symlink(path, ec))
  {
    const std::filesystem::path t = std::filesystem::weakly_canonical(path, ec);
    if(!ec)
      return t.string();
  }
  return path;
}

// Devices, pipes (/dev/stdout, a fifo): written in place, not replaced.
inline bool is_special_file(const std::string& path)
{
  std::error_code ec;
  if(path.compare(0, 5, "/dev/") == 0 || path.compare(0, 6, "/proc/") == 0)
    return true;
  return std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec) &&
         !std::filesystem::is_directory(path, ec);
}

} // namespace internal

// Whether `path` can be written: its directory exists and accepts a new file
// (tried, not guessed from permission bits), and it is not a directory.
// Otherwise false, with the reason in `error`.
inline bool check_writable(const std::string& path, std::string& error)
{
  std::error_code ec;
  if(internal::is_special_file(path))
  {
    if(::access(path.c_str(), W_OK) == 0)
      return true;
    error = std::strerror(errno);
    return false;
  }
  const std::string target = internal::resolved_target(path);
  const std::filesystem::path dir = internal::directory_of(target);
  if(!std::filesystem::is_directory(dir, ec))
  {
    error = "directory '" + dir.string() + "' does not exist";
    return false;
  }
  if(std::filesystem::is_directory(path, ec))
  {
    error = "it is a directory";
    return false;
  }
  const std::string probe = internal::make_temporary_beside(target);
  if(probe.empty())
  {
    error = std::string("cannot create a file in '") + dir.string() + "': " + std::strerror(errno);
    return false;
  }
  std::remove(probe.c_str());
  return true;
}

// Whether `a` and `b` name the same file (also through links and "./").
inline bool same_file(const std::string& a, const std::string& b)
{
  std::error_code ea, eb;
  if(std::filesystem::exists(a, ea) && std::filesystem::exists(b, eb))
    return std::filesystem::equivalent(a, b, ea) && !ea;
  auto resolved = [](const std::string& p) {
    std::error_code ec;
    const std::filesystem::path abs = std::filesystem::absolute(p, ec);
    const std::filesystem::path c = std::filesystem::weakly_canonical(abs, ec);
    return (ec ? abs : c).lexically_normal();
  };
  return resolved(a) == resolved(b);
}

// Calls `write(temporary_path)` and renames the temporary file over `path`
// if it returned true; otherwise removes it and leaves `path` as it was.
// A device or a pipe is written in place; a link is followed.
template <typename Write>
bool write_atomically(const std::string& output, Write write)
{
  if(internal::is_special_file(output))
    return write(output);
  const std::string path = internal::resolved_target(output);
  const std::string tmp = internal::make_temporary_beside(path);
  if(tmp.empty())
    return false;
  bool ok = false;
  try
  {
    ok = write(tmp);
  }
  catch(...)
  {
    std::remove(tmp.c_str());
    throw;
  }
  if(ok && std::rename(tmp.c_str(), path.c_str()) == 0)
    return true;
  std::remove(tmp.c_str());
  return false;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_OUTPUT_FILES_H
