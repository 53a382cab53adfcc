#include "rackopt/study/fe_verification.hpp"

#include <exception>
#include <memory>
#include <string>

#include "rackopt/core/error.hpp"
#include "rackopt/core/interrupt.hpp"
#include "rackopt/fe/ccx_runner.hpp"

namespace rackopt::study {

fe::FeComparisonOptions fe_verification_options(const FeVerifySpec& verify, const RunOptions& options) {
  fe::FeComparisonOptions o;
  o.positions = verify.positions;
  o.fe.level = verify.level;
  o.fe.extended_contact = verify.extended_contact;
  o.fe.rack_on_supports = verify.rack_supports;
  o.threads = options.threads;
  o.calls = options.fe_calls;
  o.stop = options.stop;
  return o;
}

void verify_best_design_by_fe(const StudySpec& spec, const RunOptions& options, StudyResult& result) {
  if (!spec.verify_fe) return;
  if (result.status == StudyStatus::kStopped) {
    result.fe_verification_error = "not run: the study was stopped before it ended";
    return;
  }
  if (!result.best_drive) {
    result.fe_verification_error = "not run: the study has no design to verify (no feasible design computed)";
    return;
  }
  try {
    result.fe_verification = std::make_shared<const fe::FeComparison>(
        fe::compare_with_fe(*result.best_drive, fe_verification_options(*spec.verify_fe, options)));
  } catch (const Interrupted& e) {
    // The stop ends the study, not only its verification: stopped, so that
    // the report, summary.json and the exit status all say so.
    result.status = StudyStatus::kStopped;
    result.stopped_during = "the FE verification of the best design";
    result.fe_verification_error = std::string("not finished: ") + e.what();
  } catch (const fe::CcxError& e) {
    result.fe_verification_error = std::string("FE solve failed: ") + e.what();
    if (!e.deck().empty() && result.fe_verification_error.find(e.deck()) == std::string::npos) {
      result.fe_verification_error += " (input deck kept: " + e.deck() + ")";
    }
  } catch (const DesignError& e) {
    result.fe_verification_error = "impossible FE model of the design (" + e.code() + "): " + e.what();
  } catch (const std::exception& e) {
    result.fe_verification_error = e.what();
  }
}

}  // namespace rackopt::study
