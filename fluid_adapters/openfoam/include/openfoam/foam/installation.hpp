#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace openfoam {

// Where the stock OpenFOAM applications are. Debian's v1912 ships them in
// /usr/bin with its etc directory in /usr/share/openfoam; its etc/bashrc is
// broken, and WM_PROJECT_DIR alone is what the applications need to find
// etc/controlDict.
struct Installation {
  std::filesystem::path project_dir;  // WM_PROJECT_DIR
  std::map<std::string, std::filesystem::path> applications;

  const std::filesystem::path& application(const std::string& name) const;
};

// Finds the applications `names` on PATH and the project directory
// (WM_PROJECT_DIR when set, else /usr/share/openfoam, holding
// etc/controlDict), and sets WM_PROJECT_DIR for the applications started
// later (and PWD, which they expect to be the working directory). OpenFOAM
// missing throws cosim::InputError (exit 2) saying how to install it.
Installation find_installation(const std::vector<std::string>& names);

// The message the adapter prints when OpenFOAM is missing (also used by the
// tests that need OpenFOAM to say why they are not run).
std::string installation_hint();

}  // namespace openfoam
