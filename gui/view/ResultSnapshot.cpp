#include "view/ResultSnapshot.hpp"

#include "model/Model.hpp"
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
    // The solver's stresses are effective; the picture's "stress" is the total stress σ = σ′ − u,
    // as RunOutput writes it, so the live picture and the saved steps agree.
    if (has_water(simulation.full_model())) r.pore_pressure = simulation.pore_pressures();
    const bool water = r.pore_pressure.size() == s.stress.size() && !r.pore_pressure.empty();
    r.stress.reserve(s.stress.size());
    for (std::size_t e = 0; e < s.stress.size(); ++e) {
        const std::array<double, 4> effective{s.stress[e][0], s.stress[e][1], e < s.stress_zz.size() ? s.stress_zz[e] : 0.0,
                                              s.stress[e][2]};
        const double u = water ? r.pore_pressure[e] : 0.0;
        r.stress.push_back({effective[0] - u, effective[1] - u, effective[2] - u, effective[3]});
        if (water) r.effective_stress.push_back(effective);
    }
    if (!water) r.pore_pressure.clear();
    r.plastic_strain = s.plastic_strain;
    r.plastic_state = s.plastic_state;
    r.present.assign(simulation.active_elements().begin(), simulation.active_elements().end());
    return r;
}

}  // namespace mcdda
