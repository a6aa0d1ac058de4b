#include "ice/io/run_ranks.hpp"

#include "ice/case/make_solver.hpp"

namespace ice {

template <int Dim>
std::unique_ptr<IceSolver<Dim>> RunRanks<Dim>::make_solver(const CaseDescription& description) {
  return ice::make_solver<Dim>(description);
}

template <int Dim>
std::unique_ptr<cosim::SnapshotSink> RunRanks<Dim>::snapshots(
    const std::filesystem::path& directory, const std::string& base_name,
    const cosim::Mesh& cells) {
  return std::make_unique<cosim::SnapshotWriter>(directory, base_name, cells);
}

template class RunRanks<1>;
template class RunRanks<2>;
template class RunRanks<3>;

}  // namespace ice
