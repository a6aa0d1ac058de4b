#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "cosim/config/node.hpp"
#include "cosim/fields.hpp"
#include "job/coupling_spec.hpp"
#include "job/job.hpp"

namespace cosim::job {

namespace {

// The fields the coupler sends `participant`: the exchanges' and the
// exchange steps' (check_reads_provided has made sure every read is one).
bool coupler_sends(const Job& job, const std::string& participant, const std::string& field) {
  const ParticipantSpec* p = job.participant(participant);
  return p && p->reads.count(field) > 0;
}

SentField sent_field(const Job& job, const config::Node& node) {
  const auto label = node.as<std::string>();
  const auto dot = label.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == label.size())
    node.fail(fmt::format("'{}' is not <participant>.<field>", label));
  SentField f{label.substr(0, dot), label.substr(dot + 1)};
  const ParticipantSpec* p = job.participant(f.participant);
  if (!p) node.fail(fmt::format("no participant named '{}'", f.participant));
  if (!coupler_sends(job, f.participant, f.field)) {
    std::string reads;
    for (const auto& [name, mesh] : p->reads) reads += (reads.empty() ? "" : ", ") + name;
    node.fail(fmt::format("the coupler sends participant '{}' no field '{}' (it sends: {})",
                          f.participant, f.field, reads.empty() ? "none" : reads));
  }
  return f;
}

acceleration::AccelerationSpec read_acceleration(const config::Node& a,
                                                 const std::set<std::string>& written) {
  using namespace acceleration;
  AccelerationSpec spec;
  const auto method = a.get<std::string>("method");
  spec.method = method == "iqn-ils"    ? Method::iqn_ils
                : method == "iqn-imvj" ? Method::iqn_imvj
                : method == "aitken"   ? Method::aitken
                                       : Method::constant;
  spec.relaxation = method == "none" ? 1.0 : a.get<double>("relaxation");
  if (method == "none" && written.count("acceleration.relaxation"))
    a["relaxation"].fail("method none takes H(x) as it is; a relaxation needs method constant");
  spec.max_columns = a.get<std::size_t>("max_columns");
  spec.reuse_windows = a.get<std::size_t>("reuse_windows");
  const auto filter = a.get<std::string>("filter");
  spec.filter = filter == "qr1" ? Filter::qr1 : filter == "qr2" ? Filter::qr2 : Filter::none;
  spec.filter_limit = a.get<double>("filter_limit");
  const auto preconditioner = a.get<std::string>("preconditioner");
  spec.preconditioner = preconditioner == "value"          ? Preconditioner::value
                        : preconditioner == "residual-sum" ? Preconditioner::residual_sum
                        : preconditioner == "convergence"  ? Preconditioner::convergence
                                                           : Preconditioner::none;
  spec.freeze_preconditioner_after = a.get<std::size_t>("freeze_preconditioner_after");
  return spec;
}

// The momentum and the heat the coupler's exchanges give each phase are
// their answers to the window's predicted velocities and temperatures, not
// iterates to accelerate.
bool computed_by_exchange(const Job& job, const SentField& f) {
  return (job.momentum_exchange && job.momentum_exchange->solved_by == ExchangeSolver::coupler &&
          f.field == fields::momentum_exchange_impulse.name) ||
         (job.energy_exchange && f.field == fields::heat_exchange_energy.name);
}

// Serial schemes run two participants one after the other; the exchange
// steps need both phases' states of the same window at once.
void read_serial_order(const Job& job, const config::Node& c, CouplingSpec& spec) {
  if (job.participants.size() != 2)
    c["scheme"].fail(fmt::format("a serial scheme couples two participants; this job has {}",
                                 job.participants.size()));
  if (job.momentum_exchange || job.energy_exchange)
    c["scheme"].fail(
        "the momentum and energy exchanges need both phases' states of a window at once: use a "
        "parallel scheme");
  spec.first = job.participants.front().name;
  if (auto f = c.find("first")) {
    spec.first = f->as<std::string>();
    if (!job.participant(spec.first)) f->fail(fmt::format("no participant named '{}'", spec.first));
  }
  spec.second = job.participants[job.participants[0].name == spec.first ? 1 : 0].name;
}

}  // namespace

std::set<std::string> written_coupling_keys(const config::Node& root) {
  std::set<std::string> keys;
  const auto c = root.find("coupling");
  if (!c || !c->is_map()) return keys;
  for (const auto& [key, value] : c->entries()) {
    keys.insert(key);
    if (key == "acceleration" && value.is_map())
      for (const auto& [inner, v] : value.entries()) keys.insert("acceleration." + inner);
  }
  return keys;
}

CouplingSpec read_coupling(const Job& job, const config::Node& c,
                           const std::set<std::string>& written) {
  CouplingSpec spec;
  spec.where = c.location();
  spec.scheme_where = c["scheme"].location();
  const auto scheme = c.get<std::string>("scheme");
  spec.scheme = scheme == "parallel-implicit" ? Scheme::parallel_implicit
                : scheme == "serial-explicit" ? Scheme::serial_explicit
                : scheme == "serial-implicit" ? Scheme::serial_implicit
                                              : Scheme::parallel_explicit;
  if (spec.is_serial())
    read_serial_order(job, c, spec);
  else if (written.count("first"))
    c["first"].fail_at_key("'first' applies to serial schemes; this job's scheme is " + scheme);
  spec.time_interpolation = c.get<std::string>("time_interpolation") == "linear"
                                ? com::TimeInterpolation::linear
                                : com::TimeInterpolation::constant;
  spec.max_iterations = c.get<std::size_t>("max_iterations");
  spec.on_max_iterations = c.get<std::string>("on_max_iterations") == "continue"
                               ? OnMaxIterations::continue_run
                               : OnMaxIterations::stop;
  spec.divergence_factor = c.get<double>("divergence_factor");

  if (spec.scheme == Scheme::parallel_explicit && written.count("time_interpolation"))
    c["time_interpolation"].fail_at_key(
        "'time_interpolation' reads a partner's window-end values inside the window, which a "
        "parallel-explicit scheme does not have yet (use serial-explicit, an implicit scheme, "
        "or the job's 'extrapolation: linear')");
  if (!spec.is_implicit()) {
    for (const char* key : {"convergence", "acceleration", "max_iterations", "on_max_iterations",
                            "divergence_factor"})
      if (written.count(key))
        c[key].fail_at_key(
            fmt::format("'{}' applies to implicit schemes; this job's scheme is {}", key, scheme));
    return spec;
  }
  const auto measures = c.find("convergence");
  if (!measures || measures->size() == 0)
    c.fail_at_key(
        "an implicit scheme needs at least one convergence measure (coupling.convergence)");
  for (const config::Node& m : measures->items()) {
    ConvergenceMeasure measure;
    measure.field = sent_field(job, m["field"]);
    measure.where = m.location();
    measure.key_path = m.key_path();
    if (auto r = m.find("relative")) measure.relative = r->as<double>();
    if (auto a = m.find("absolute")) measure.absolute = a->as<double>();
    if (auto r = m.find("residual_relative")) measure.residual_relative = r->as<double>();
    if (!measure.relative && !measure.absolute && !measure.residual_relative)
      m.fail("a convergence measure needs a limit: relative, absolute or residual_relative");
    for (const ConvergenceMeasure& other : spec.convergence)
      if (other.field.label() == measure.field.label())
        m["field"].fail(fmt::format("'{}' has a convergence measure already (at {})",
                                    measure.field.label(), other.key_path));
    spec.convergence.push_back(std::move(measure));
  }

  const config::Node a = c["acceleration"];
  spec.acceleration = read_acceleration(a, written);
  if (auto fields = a.find("fields")) {
    for (const config::Node& f : fields->items()) {
      SentField field = sent_field(job, f);
      if (computed_by_exchange(job, field))
        f.fail(
            fmt::format("'{}' is an exchange's answer to the predicted velocities or "
                        "temperatures (architecture.md §13), never accelerated; measure it, do "
                        "not list it",
                        field.label()));
      for (const SentField& other : spec.accelerated)
        if (other.label() == field.label())
          f.fail(fmt::format("'{}' is listed twice", field.label()));
      spec.accelerated.push_back(std::move(field));
    }
    if (spec.accelerated.empty()) fields->fail("list at least one field, or leave the key out");
  } else {
    // Every field the iteration sends: one left out would answer the previous
    // iteration, so H would be no function of x alone and the quasi-Newton
    // pairs would contradict each other (architecture.md §13).
    for (const ParticipantSpec& p : job.participants)
      for (const auto& [field, mesh] : p.reads) {
        SentField f{p.name, field};
        if (!computed_by_exchange(job, f) && (!spec.is_serial() || p.name == spec.first))
          spec.accelerated.push_back(std::move(f));
      }
  }
  if (spec.is_serial())
    for (const SentField& f : spec.accelerated)
      if (f.participant != spec.first)
        a["fields"].fail(fmt::format(
            "'{}': a serial scheme accelerates what the coupler sends the first participant, "
            "'{}'",
            f.label(), spec.first));
  return spec;
}

}  // namespace cosim::job
