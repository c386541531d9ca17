#pragma once
// The particle data contract between readers, filters and representations: the names of the point
// arrays and of the scene constants in field data. Nobody writes these names as literals.
namespace parafluid::contract
{
// Point arrays.
constexpr const char* Velocity = "velocity";         // 3 components [m/s]
constexpr const char* Density = "density";           // [kg/m^3]
constexpr const char* Pressure = "pressure";         // [Pa]
constexpr const char* Mass = "mass";                 // [kg]
constexpr const char* Acceleration = "acceleration"; // 3 components [m/s^2]
constexpr const char* Id = "id";                     // int64, stable across time steps
constexpr const char* NeighbourCount = "neighbour_count";
// Field data: the scene constants.
constexpr const char* ParticleSpacing = "particle_spacing"; // lattice spacing d [m]
constexpr const char* SmoothingLength = "smoothing_length"; // h [m]
constexpr const char* RestDensity = "rest_density";         // [kg/m^3]
constexpr const char* DomainBounds = "domain_bounds";       // xmin xmax ymin ymax zmin zmax [m]
constexpr const char* ParticleMass = "particle_mass";       // [kg]
constexpr const char* Time = "time";                        // [s]
} // namespace parafluid::contract
