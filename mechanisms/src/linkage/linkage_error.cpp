// TEMPORARY (lead's branch): replaced by the reader's implementation in linkage_description.cpp.
#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms {

namespace {
std::string located(const std::string& file, SourcePlace place, const std::string& problem) {
  if (place.line <= 0) return file + ": " + problem;
  return file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) + ": " + problem;
}
}  // namespace

LinkageFileError::LinkageFileError(const std::string& file, SourcePlace place, const std::string& problem)
    : std::invalid_argument(located(file, place, problem)), problem_(problem), place_(place) {}

int LinkageDescription::joint_index(std::string_view name) const {
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].name == name) return static_cast<int>(j);
  }
  return -1;
}

}  // namespace numlab::mechanisms
