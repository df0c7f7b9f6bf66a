#include "view/ResultSnapshot.hpp"

#include "run/Simulation.hpp"

namespace mcdda {

ResultSnapshot ResultSnapshot::of(const Simulation& simulation)
{
    const SimulationState& s = simulation.state();
    ResultSnapshot r;
    r.step = s.step;
    r.total_steps = simulation.planned_steps();
    r.time = s.time;
    r.stage = s.stage + 1;
    r.displacement.assign(s.displacement.data(), s.displacement.data() + s.displacement.size());
    r.stress.reserve(s.stress.size());
    for (std::size_t e = 0; e < s.stress.size(); ++e)
        r.stress.push_back({s.stress[e][0], s.stress[e][1], e < s.stress_zz.size() ? s.stress_zz[e] : 0.0, s.stress[e][2]});
    r.plastic_strain = s.plastic_strain;
    r.plastic_state = s.plastic_state;
    r.present.assign(simulation.active_elements().begin(), simulation.active_elements().end());
    return r;
}

}  // namespace mcdda
