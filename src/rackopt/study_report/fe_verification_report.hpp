// The `verify: fe` part of a study's report: fe.csv and fe_stiffness.png in
// the study folder, the section "FE verification of the optimum" of
// report.md and the "fe_verification" object of summary.json (docs/output.md,
// "Study results"; the columns and keys are those of `rackopt fe`, docs/fe.md).
#pragma once

#include <functional>
#include <string>

#include "rackopt/output/json_writer.hpp"
#include "rackopt/study_report/study_report.hpp"
#include "rackopt/study_report/study_types.hpp"

namespace rackopt::study_report {

// Writes fe.csv (role "fe_csv") through `write` and fe_stiffness.png (role
// "fe_png") through `plot`, when the study has an FE comparison. `write(name,
// content)` returns the path; `plot(role, script_name, script, png)` as
// write_study_report's own.
void write_fe_verification_files(
    const StudySpec& spec, const StudyResult& result, ReportFiles& files,
    const std::function<std::string(const std::string&, const std::string&)>& write,
    const std::function<void(const std::string&, const std::string&, const std::string&, const std::string&)>& plot);

// "## FE verification of the optimum" with the table and the summary, or
// what kept it from being made; "" without `verify: fe`.
std::string fe_verification_markdown(const StudySpec& spec, const StudyResult& result);

// Key "fe_verification" of summary.json (nothing without `verify: fe`):
// {requested {positions, level, extended_contact}, ok, error, and with ok
// the JSON object of `rackopt fe` as "comparison"}.
void fe_verification_json(JsonWriter& j, const StudySpec& spec, const StudyResult& result);

}  // namespace rackopt::study_report
