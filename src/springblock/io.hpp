#pragma once
// Output files are written whole or not at all: to a temporary file beside the target, then
// renamed over it. Every results file carries the metadata needed to reproduce it.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "springblock/ensemble.hpp"
#include "springblock/scene.hpp"

namespace sb {

// Write `content` to `path` atomically (temporary file in the same directory, fsync, rename).
// Throws std::runtime_error naming the path on failure; no partial file is left behind.
void write_file_atomic(const std::string& path, const std::string& content);

// Refuse an output path before anything is simulated: creates and removes the temporary file
// write_file_atomic would use, so a missing or unwritable directory, or a directory given as the
// file, fails now rather than after the run. Throws InputError(field, ...) naming the path.
void check_writable(const std::string& path, const std::string& field);

// Why a statistic of `result` has no value, or "" when it has one: JSON puts it beside the nulls
// (`not_measured`) and the text output prints it in place of a number. `quantity` is "mu_s" or
// "mu_d" (mu_d_signed shares mu_d's reason).
std::string not_measured(const Scene& scene, const EnsembleResult& result, const std::string& quantity);
// The same for an observable of observables.hpp: its reason is its summary kind's (the loading
// phase's for Summary::Loading, the mu_d window's for Summary::Window), "" for the others.
std::string not_measured(const Scene& scene, const EnsembleResult& result, const Observable& o);

// Provenance: program version, commit, command line, UTC time, host threads.
nlohmann::json provenance(const std::string& command_line);

// The full results object of an ensemble: the results schema (mu_s, mu_d with mean/std/sem,
// reps, seed, contact_fraction, method, dt, duration, wall_seconds) plus the scene, derived
// parameters, per-repetition values and provenance; with the scene's slip_events, their summary
// (slip_event_summary) and each repetition's events (runs[].slip_events).
nlohmann::json ensemble_json(const Scene& scene, const EnsembleResult& result,
                             const std::string& command_line);

// mu(t) series of repetition 0 as TSV with a commented header of the same metadata.
std::string series_tsv(const Scene& scene, const EnsembleResult& result, const std::string& command_line);

}  // namespace sb
