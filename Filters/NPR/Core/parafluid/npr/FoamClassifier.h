#pragma once
// Foam and crest particles for illustration. Per frame, each particle gets a score from two cues:
//  - crest: a surface particle (colour-field gradient |grad c| h above SurfaceThreshold, with
//    c = sum_j V W_poly6) on a convex, sharply curved surface. Its crest potential, after Ihmsen
//    et al. 2012 ("Unified spray, foam and bubbles for particle-based fluids"), sums
//    (1 - n_i . n_j)(1 - r/h) over surface neighbours j lying below it along its outward normal
//    n_i, so flat or gently curved surfaces score about 0 and crests score high;
//  - spray: few neighbours within h (a particle flying free of the bulk).
// score = max(crest potential / CrestThreshold, spray cue), candidate where score >= 1.
// Over time, FoamHysteresis switches a particle (by its stable id) to foam only after it has been a
// candidate for PersistFrames frames in a row, and back after as many frames as a non-candidate,
// so foam does not flicker.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace parafluid::npr
{
struct FoamParameters
{
  double kernelRadius = 0.0;     // h [m]; the Foam Particles filter uses 3 d, which the default
                                 // thresholds are tuned for
  double particleVolume = 0.0;   // V [m^3] (d^3 for particles seeded on a lattice of spacing d)
  double surfaceThreshold = 0.4; // |grad c| h above which a particle is on the surface (about 0
                                 // inside, near 1 on a flat surface)
  double crestThreshold = 1.0;   // crest potential that makes a candidate (at h = 3 d: the apex
                                 // of a 90-degree ridge 1.2, a lattice ball of radius 10 d <= 0.44)
  int sprayNeighbours = 4;       // a particle with at most this many neighbours within h is spray
};

std::string validate(const FoamParameters& parameters);

struct FoamScores
{
  std::vector<float> score; // continuous, >= 1 for a candidate
  std::vector<std::uint8_t> candidate;
  std::vector<float> crest;          // crest potential (0 off the surface)
  std::vector<std::uint8_t> surface; // on the surface by the colour-field test
};

/// Scores n particles (x, y, z interleaved). Throws std::invalid_argument for bad parameters or
/// NaN/infinite positions.
/// `progress(fraction)` is called between blocks of particles; returning false stops the scoring
/// (the scores are then incomplete).
FoamScores scoreFoam(const float* xyz, std::size_t n, const FoamParameters& parameters,
                     const std::function<bool(double)>& progress = {});

class FoamHysteresis
{
public:
  /// Forgets every particle (for a new run, or going back in time).
  void reset() { this->States.clear(); }
  /// One frame: candidate[i] of the particle with id ids[i]; writes foam[i] (0/1). A particle not
  /// seen before starts as not foam; particles absent from this frame are forgotten.
  void update(const std::int64_t* ids, const std::uint8_t* candidate, std::size_t n, int persistFrames,
              std::vector<std::uint8_t>& foam);
  std::size_t trackedParticles() const { return this->States.size(); }

private:
  struct State
  {
    std::uint16_t run = 0; // frames in a row that disagree with `foam`
    std::uint8_t foam = 0;
  };
  std::unordered_map<std::int64_t, State> States;
};
} // namespace parafluid::npr
