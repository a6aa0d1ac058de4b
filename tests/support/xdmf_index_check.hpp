#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "hdf5_reader.hpp"
#include "text_files.hpp"
#include "xml_reader.hpp"

// Checks an XDMF index the way a reader would: well-formed XML, a temporal
// collection of the expected number of grids, every HDF DataItem naming an
// existing dataset of exactly the stated dimensions, and every attribute's
// leading dimensions matching its grid's topology and centring.
namespace cosim::testing {

inline std::vector<unsigned long long> parse_dims(const std::string& text) {
  std::istringstream in(text);
  std::vector<unsigned long long> dims;
  unsigned long long d = 0;
  while (in >> d) dims.push_back(d);
  return dims;
}

inline void check_heavy_data(const XmlElement& item, const std::filesystem::path& directory,
                             int& checked) {
  if (item.name == "DataItem" && item.attribute("Format") == "HDF") {
    const std::string& text = item.text;
    const auto colon = text.find(':');
    ASSERT_NE(colon, std::string::npos) << text;
    const std::string file = text.substr(0, colon);
    const std::string dataset = text.substr(colon + 1);
    ASSERT_TRUE(std::filesystem::exists(directory / file)) << file;
    Hdf5Reader reader(directory / file);
    ASSERT_TRUE(reader.has(dataset)) << text;
    const auto dims = reader.dims(dataset);
    EXPECT_EQ(std::vector<unsigned long long>(dims.begin(), dims.end()),
              parse_dims(item.attribute("Dimensions")))
        << text;
    ++checked;
  }
  for (const auto& child : item.children) check_heavy_data(*child, directory, checked);
}

// Leading dims an attribute must have on this grid (slowest first).
inline std::vector<unsigned long long> expected_attribute_dims(const XmlElement& grid,
                                                               const std::string& center) {
  const XmlElement& topology = grid.one("Topology");
  const std::string& type = topology.attribute("TopologyType");
  if (type == "2DCoRectMesh" || type == "3DCoRectMesh") {
    auto nodes = parse_dims(topology.attribute("Dimensions"));
    if (center == "Cell")
      for (auto& n : nodes) --n;
    return nodes;
  }
  const unsigned long long elements = std::stoull(topology.attribute("NumberOfElements"));
  if (center == "Cell") return {elements};
  const auto xyz_dims = parse_dims(grid.one("Geometry").one("DataItem").attribute("Dimensions"));
  return {xyz_dims.at(0)};
}

struct IndexCheck {
  std::unique_ptr<XmlElement> root;
  std::vector<const XmlElement*> grids;
  std::vector<double> times;
  int heavy_items = 0;
};

inline IndexCheck check_index(const std::filesystem::path& xdmf, std::size_t expected_steps) {
  IndexCheck check;
  check.root = XmlReader::parse(read_text(xdmf));
  EXPECT_EQ(check.root->name, "Xdmf");
  EXPECT_EQ(check.root->attribute("Version"), "3.0");
  const XmlElement& collection = check.root->one("Domain").one("Grid");
  EXPECT_EQ(collection.attribute("GridType"), "Collection");
  EXPECT_EQ(collection.attribute("CollectionType"), "Temporal");
  check.grids = collection.all("Grid");
  EXPECT_EQ(check.grids.size(), expected_steps);
  for (const XmlElement* grid : check.grids) {
    check.times.push_back(std::stod(grid->one("Time").attribute("Value")));
    check_heavy_data(*grid, xdmf.parent_path(), check.heavy_items);
    for (const XmlElement* attribute : grid->all("Attribute")) {
      const std::string& center = attribute->attribute("Center");
      const auto dims = parse_dims(attribute->one("DataItem").attribute("Dimensions"));
      const auto leading = expected_attribute_dims(*grid, center);
      EXPECT_EQ(std::vector<unsigned long long>(dims.begin(),
                                                dims.begin() + static_cast<long>(leading.size())),
                leading)
          << attribute->attribute("Name");
      const std::string& type = attribute->attribute("AttributeType");
      const std::size_t trailing = dims.size() - leading.size();
      const std::map<std::string, unsigned long long> components{
          {"Scalar", 1}, {"Vector", 3}, {"Tensor6", 6}, {"Tensor", 9}};
      if (type == "Scalar") {
        EXPECT_EQ(trailing, 0u) << attribute->attribute("Name");
      } else if (components.contains(type)) {
        EXPECT_EQ(trailing, 1u);
        EXPECT_EQ(dims.back(), components.at(type)) << attribute->attribute("Name");
      }
    }
  }
  return check;
}

}  // namespace cosim::testing
