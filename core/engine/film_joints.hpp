#pragma once
/// @file The lubricated joints of a case: the mapping from the case's skirt, big-end, lubricant
/// and surface fields to the coupling elements' plain solver configurations and mountings, and
/// the factories BuildCrankTrain uses for the lubricated models.
#include <filesystem>
#include <memory>
#include <string>

#include "core/engine/crank_train.hpp"
#include "core/engine/engine_case.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

namespace filmdyn::engine {

/// The oil a joint's film carries: the case's lubricant or the joint's own (JointOil::source),
/// and the prefix of its fields ("lubricant." or "<joint>.oil.").
const lubrication::OilSpec& JointOilSpec(const EngineCase& c, const JointOil& oil);
/// True when the joint's oil does not depend on its film temperature (a constant viscosity:
/// its pressure and shear laws then do not either).
bool TemperatureFreeOil(const EngineCase& c, const JointOil& oil);
std::string JointOilPrefix(const JointOil& oil, const std::string& joint);
/// A joint's oil at its film temperature (JointOilSpec). Throws filmdyn::InputError naming the
/// field ("lubricant.vogel_a", "skirt.oil.temperature").
lubrication::OilSpec::AtTemperature JointOilAt(const EngineCase& c, const JointOil& oil,
                                               const std::string& joint);
/// The film temperature a run starts a joint at [K]: the given one, or with a heat balance the
/// larger of it and the supply temperature (the balance only heats the film from there).
double StartFilmTemperature(const EngineCase& c, const JointOil& oil);
/// Throws InputError naming the field when a lubricated joint's oil cannot be evaluated at the
/// temperature its run starts at (JointOilAt: a Vogel pole at or above it, a catalogue oil
/// outside its range, a law's constants out of range): the check the run makes first, made with
/// the case so that the case editor and the case file find it too. Joints not lubricated are
/// not checked (their oil is not used).
void CheckJointOils(const EngineCase& c);
/// The bulk modulus a joint's film runs with [Pa]: its oil's (JointOilSpec) with
/// mass-conserving cavitation, 0 (incompressible) with the Reynolds condition. Throws InputError
/// naming the oil's bulk_modulus field when it is out of range, or set together with a
/// pressure-viscosity law in a mass-conserving film.
double JointBulkModulus(const EngineCase& c, const JointOil& oil, const std::string& joint,
                        lubrication::CavitationModel cavitation);

/// The skirt solver configuration of a case (mesh: the case's counts). Throws InputError naming
/// the field when the case has no skirt clearance or its surfaces are invalid. An imported
/// compliance is read from `skirt.compliance_file`, a relative name resolved against
/// `case_directory` (empty: the working directory).
lubrication::SkirtConfig SkirtConfigFromCase(const EngineCase& engine_case,
                                             const std::filesystem::path& case_directory = {});
/// Whether the big end's film is solved over the symmetric half of the width: the planar model
/// keeps the journal parallel to the bearing and every feed on the mid-plane, so the film is
/// symmetric about it; an even axial count of at least 4 has a node row there.
bool BigEndSolvesSymmetricHalf(const BigEndCase& big_end);
/// The bearing solver configuration of a case (SurfaceModel from roughness, E and ν, μ_f, K). An
/// imported compliance is read from `big_end.compliance_file`, a relative name resolved against
/// `case_directory` (empty: the working directory).
lubrication::BearingConfig BearingConfigFromCase(const EngineCase& engine_case,
                                                 const std::filesystem::path& case_directory = {});

/// The lubricated skirt element of a case (liner = ground, the layout's piston).
std::unique_ptr<multibody::JointForceElement> MakeLubricatedSkirt(
    const EngineCase& engine_case, const CrankTrainLayout& layout,
    const std::filesystem::path& case_directory = {});
/// The lubricated big-end element of a case (journal on the crank, bearing on the rod).
std::unique_ptr<multibody::JointForceElement> MakeLubricatedBigEnd(
    const EngineCase& engine_case, const CrankTrainLayout& layout,
    const std::filesystem::path& case_directory = {});
/// The film meshes of a case in words, e.g. "skirt 15 + 2 + 15 x 20 elements; big end 100 x 10
/// elements, graded 8:1 around and 4:1 across".
std::string DescribeMeshes(const EngineCase& engine_case);
/// Sets the paper's meshes (Table II: skirt 30 + 2 + 30 x 40, big end 50 x 10 uniform).
void UsePaperMeshes(EngineCase* engine_case);

/// Both factories: what RunConfig uses for the lubricated models.
LubricatedJointFactories FilmJointFactories(const std::filesystem::path& case_directory = {});

}  // namespace filmdyn::engine
