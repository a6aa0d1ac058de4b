// The catalogue of exchanged fields (cosim/fields.hpp): one entry a name, and
// every field a shipped job lets a solver write or read is in it, with the
// mapping its job gives it.
#include "cosim/fields.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
namespace fields = cosim::fields;

TEST(Fields, NamesAreUniqueAndFound) {
  std::set<std::string> names;
  for (const fields::Field* field : fields::all()) {
    EXPECT_TRUE(names.insert(field->name).second) << field->name;
    EXPECT_EQ(fields::find(field->name), field);
    EXPECT_FALSE(std::string(field->unit).empty()) << field->name;
    EXPECT_FALSE(std::string(field->meaning).empty()) << field->name;
  }
  EXPECT_EQ(fields::find("no_such_field"), nullptr);
}

TEST(Fields, WindowIntegralsAreExtensive) {
  for (const fields::Field* field : fields::all()) {
    if (field->time == cosim::TimeTreatment::integral) {
      EXPECT_EQ(field->quantity, cosim::Quantity::extensive) << field->name;
    }
  }
}

TEST(Fields, DeclarationCarriesTheCatalogue) {
  const cosim::FieldSpec spec = fields::momentum_exchange_impulse.on("grid", 3);
  EXPECT_EQ(spec.name, "momentum_exchange_impulse");
  EXPECT_EQ(spec.mesh, "grid");
  EXPECT_EQ(spec.components, 3);
  EXPECT_EQ(spec.unit, "kg m/s");
  EXPECT_EQ(spec.quantity, cosim::Quantity::extensive);
  EXPECT_EQ(spec.time, cosim::TimeTreatment::integral);
  EXPECT_EQ(fields::pore_pressure.on("grid", 3).components, 1);
}

TEST(Fields, HelpListsEveryField) {
  const std::string help = fields::help();
  for (const fields::Field* field : fields::all())
    EXPECT_NE(help.find(field->name), std::string::npos) << field->name;
}

bool is_solver(const std::string& executable) {
  return executable == "mpm_solver" || executable == "ice_fluid" || executable == "swe_fluid" ||
         executable == "openfoam_adapter";
}

TEST(Fields, EveryFieldOfTheShippedJobsIsInTheCatalogue) {
  int jobs = 0, checked = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(COSIM_SOURCE_DIR) / "configs")) {
    if (entry.path().extension() != ".yaml") continue;
    const YAML::Node root = YAML::LoadFile(entry.path().string());
    if (!root.IsMap() || !root["kind"] || root["kind"].as<std::string>() != "job") continue;
    ++jobs;
    std::set<std::string> solver_participants;
    for (const auto& participant : root["participants"]) {
      if (!is_solver(participant.second["executable"].as<std::string>())) continue;
      solver_participants.insert(participant.first.as<std::string>());
      for (const char* direction : {"writes", "reads"})
        for (const auto& field : participant.second[direction]) {
          ++checked;
          EXPECT_NE(fields::find(field.first.as<std::string>()), nullptr)
              << entry.path() << ": " << field.first.as<std::string>();
        }
    }
    for (const auto& exchange : root["exchange"]) {
      if (!solver_participants.count(exchange["from"].as<std::string>())) continue;
      const fields::Field* field = fields::find(exchange["field"].as<std::string>());
      ASSERT_NE(field, nullptr) << entry.path();
      if (!exchange["mapping"]) continue;
      const std::string mapping = exchange["mapping"].as<std::string>();
      EXPECT_EQ(mapping == "conservative", field->quantity == cosim::Quantity::extensive)
          << entry.path() << ": " << field->name << " mapped " << mapping;
    }
  }
  std::printf("%d jobs, %d solver field declarations checked\n", jobs, checked);
  EXPECT_GT(jobs, 10);
  EXPECT_GT(checked, 100);
}

}  // namespace
