// Runs wheelrail on a parameter file that must be rejected: prints its output
// and exit status; exits 0 only if wheelrail failed with a non-zero status.
// The file is copied into the working directory (the test's own directory in
// the build tree) and named bare, as a user in the case's directory types it:
// `wheelrail case.prm`. Files beside it named NAME.*.inc (parameter files that
// NAME.prm includes) are copied with it.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  if (argc != 2)
    return 2;
  const std::filesystem::path source(argv[1]);
  const std::filesystem::path name = source.filename();
  std::filesystem::copy_file(source, name, std::filesystem::copy_options::overwrite_existing);
  const std::string stem = source.stem().string() + ".";
  for (const auto &entry : std::filesystem::directory_iterator(source.parent_path()))
    {
      const std::string file = entry.path().filename().string();
      if (file.compare(0, stem.size(), stem) == 0 && entry.path().extension() == ".inc")
        std::filesystem::copy_file(entry.path(),
                                   file,
                                   std::filesystem::copy_options::overwrite_existing);
    }
  const std::string command = std::string(WHEELRAIL_EXECUTABLE) + " '" + name.string() + "' 2>&1";
  FILE             *pipe    = popen(command.c_str(), "r");
  if (!pipe)
    return 2;
  char buffer[4096];
  while (fgets(buffer, sizeof(buffer), pipe))
    std::cout << buffer;
  const int status = pclose(pipe);
  const int code   = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  std::cout << "exit status: " << (code != 0 ? "non-zero" : "zero") << std::endl;
  return code != 0 ? 0 : 1;
}
