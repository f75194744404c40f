#pragma once
// cli/study_job: one job of a study (issue 37 step 5, docs/study.md): its varied values applied
// to the base and the run to its end, headless; and the check, before any job runs, that every
// axis of the study applies to its base.
//
// Purpose: what `ncsim study job` (one array task) and `ncsim study run` (every job on local
// threads) call, so both give the same row. Inputs: a validated scenario::StudyFile and one
// runner::StudyJob. Outputs: the job's runner::StudyOutcome (exit category, stop reason, error
// id and first line, machining time, workpieces, audit verdict).
// How the values apply (decision, docs/study.md "What each axis changes"):
// - belt_velocity: a program base's belt as `ncsim sweep` sets it (cli/line_world: an encoder
//   belt's velocity and profile scaled, a spindle belt's MC_MoveVelocity overridden), a line's
//   encoder belt scaled the same way; every #SYNC IN's CONV_VEL follows (sweep's `follow`).
// - pitch: the `[conveyor.workpieces]` series' pitch (a series by travel; above its length).
// - fluctuation: the `[conveyor] fluctuation` amplitude in % (its frequency is the base's).
// - seed: the seed of every random part of the world: the series' scatter and the encoder noise.
// - program, machine: the program base's program and machine folder.
// An axis that changes nothing in the base (no such part of its world) is NC7206 at the axis,
// found by check_study_base before any job runs; the base's files that do not exist are NC7205.
// Invariants: a job is a function of the study file and its index only (no clock, no host);
// never throws for a bad base (the row says what happened).

#include <string>

#include "runner/study.hpp"
#include "scenario/study_file.hpp"

namespace ncsim::cli {

/// NC7205: a file the study names does not exist.
inline constexpr const char* kStudyNoFileId = "NC7205";
/// NC7206: an axis the base cannot vary (its world has no such part).
inline constexpr const char* kStudyAxisId = "NC7206";

/// Runs job `job` of `study` to its end.
runner::StudyOutcome run_study_job(const scenario::StudyFile& study, const runner::StudyJob& job);

/// The base's files exist (NC7205) and every axis applies to the base (NC7206), positioned in
/// the study file; the diagnostics (with the study file's source lines) are appended to
/// `messages`. Loads the base once per program x machine, runs nothing. False on any error.
bool check_study_base(const scenario::StudyFile& study, std::string& messages);

}  // namespace ncsim::cli
