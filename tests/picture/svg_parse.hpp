// An outside check of the SVG the picture module writes: Python's XML parser reads the document,
// and its root tag and the count of each kind of element come back, e.g. "svg path=3 rect=1".
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "temporary_files.hpp"

namespace hocav::picture_test {

inline std::string parsed_svg_outline(const std::string& document) {
  const std::filesystem::path file = testing_support::temporary_path("outline.svg");
  std::ofstream(file) << document;
  const std::string command =
      "/usr/bin/python3 -c 'import collections, sys, xml.etree.ElementTree as E\n"
      "root = E.parse(sys.argv[1]).getroot()\n"
      "tag = lambda e: e.tag.split(\"}\")[-1]\n"
      "counts = collections.Counter(tag(e) for e in root.iter() if e is not root)\n"
      "print(tag(root), \" \".join(f\"{k}={counts[k]}\" for k in sorted(counts)))' '" +
      file.string() + "' 2>&1";
  std::string outline;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    while (fgets(buffer, sizeof buffer, pipe)) outline += buffer;
    EXPECT_EQ(pclose(pipe), 0) << "not well-formed XML: " << outline;
  }
  std::filesystem::remove(file);
  while (!outline.empty() && outline.back() == '\n') outline.pop_back();
  return outline;
}

// The count of `element` in an outline "svg defs=1 path=12 ..." (0 when absent).
inline int element_count(const std::string& outline, const std::string& element) {
  const std::size_t at = outline.find(" " + element + "=");
  return at == std::string::npos ? 0 : std::stoi(outline.substr(at + element.size() + 2));
}

}  // namespace hocav::picture_test
