#include "exchange/drag_law_registry.hpp"

#include <filesystem>
#include <utility>

#include "cosim/error.hpp"
#include "exchange/beetstra.hpp"
#include "exchange/constant_drag.hpp"
#include "exchange/forchheimer.hpp"
#include "exchange/kozeny_carman.hpp"

namespace cosim::exchange {

DragLawRegistry& DragLawRegistry::instance() {
  return config::builtin_table(&register_builtin_drag_laws);
}

void register_builtin_drag_laws(DragLawRegistry& registry) {
  registry.add(std::string(KozenyCarman::law), KozenyCarman::schema(), &KozenyCarman::make);
  registry.add(std::string(Forchheimer::law), Forchheimer::schema(), &Forchheimer::make);
  registry.add(std::string(Beetstra::law), Beetstra::schema(), &Beetstra::make);
  registry.add(std::string(ConstantDrag::law), ConstantDrag::schema(), &ConstantDrag::make);
}

std::unique_ptr<DragLaw> make_drag_law(const YAML::Node& node, const std::string& key_path,
                                       const std::string& file) {
  auto source = std::make_shared<const config::SourceFile>(
      config::SourceFile{file, std::filesystem::path(file).parent_path()});
  if (!node.IsDefined()) {
    throw InputError(config::location_in(*source, YAML::Mark::null_mark()), key_path,
                     "missing: a map with a key 'law' is required");
  }
  return make_drag_law(config::Node(node, std::move(source), key_path, node.Mark()));
}

}  // namespace cosim::exchange
