#include "rackopt/study_report/fe_verification_report.hpp"

#include <sstream>

#include "rackopt/fe/fe_comparison_report.hpp"

namespace rackopt::study_report {

// The report reads the study layer's results and settings throughout.
using namespace rackopt::study;

void write_fe_verification_files(
    const StudySpec& spec, const StudyResult& result, ReportFiles& files,
    const std::function<std::string(const std::string&, const std::string&)>& write,
    const std::function<void(const std::string&, const std::string&, const std::string&, const std::string&)>& plot) {
  if (!spec.verify_fe || !result.fe_verification) return;
  const fe::FeComparison& c = *result.fe_verification;
  files.add("fe_csv", write("fe.csv", fe::fe_comparison_csv(c)));
  const std::string title = spec.name.empty() ? std::string("study") : spec.name;
  plot("fe_png", "fe_stiffness.gp", fe::fe_comparison_gnuplot(c, title, "fe_stiffness.png.tmp"), "fe_stiffness.png");
}

std::string fe_verification_markdown(const StudySpec& spec, const StudyResult& result) {
  if (!spec.verify_fe) return "";
  std::ostringstream o;
  const std::string which = spec.kind == StudyKind::kPareto ? "chosen design" : "best design";
  o << "## FE verification of the optimum\n\n";
  if (!result.fe_verification) {
    o << "The " << which << " was not verified by FE: " << result.fe_verification_error << "\n\n";
    return o.str();
  }
  o << "The " << which << " against the FE reference (docs/fe.md): "
    << fe::fe_comparison_markdown(*result.fe_verification) << "\n";
  return o.str();
}

void fe_verification_json(JsonWriter& j, const StudySpec& spec, const StudyResult& result) {
  if (!spec.verify_fe) return;
  j.key("fe_verification").begin_object();
  j.key("requested").begin_object();
  j.key("positions").value(spec.verify_fe->positions);
  j.key("level").value(spec.verify_fe->level);
  j.key("extended_contact").value(spec.verify_fe->extended_contact);
  j.end_object();
  j.key("ok").value(result.fe_verification != nullptr);
  if (result.fe_verification) {
    fe::FeFiles files;  // the study's summary lists the files under "files"
    j.key("comparison").raw(fe::fe_comparison_json(result.best_drive ? *result.best_drive : Drive{},
                                                    *result.fe_verification, files, {}));
  } else {
    j.key("error").value(result.fe_verification_error);
  }
  j.end_object();
}

}  // namespace rackopt::study_report
