#include "core/io/input_file.hpp"

#include <sys/stat.h>


namespace fp {

std::string input_file_problem(const std::string& path) {
  if (path.find('\0') != std::string::npos) return "has a NUL byte in its name";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";  // missing or unreadable: the caller's open() says why
  if (S_ISDIR(st.st_mode)) return "is a folder";
  if (!S_ISREG(st.st_mode)) return "is not a regular file (a device, pipe or socket)";
  return "";
}

}  // namespace fp
