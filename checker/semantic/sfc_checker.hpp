// Checks the structure of a textual Sequential Function Chart (IEC 61131-3 2nd ed. 2.6; OpenPCS
// manual L2446-2605): what the steps, transitions and actions of one body say about each other.
// The code inside them (conditions, action bodies) is BodyChecker's and IlChecker's.
//
// - every step a TRANSITION leaves FROM or goes TO exists, and is a step (E410; OpenPCS "Init1
//   is not a valid jump target", also when the name is a transition's);
// - step, action and transition names are unique (E003);
// - each network, i.e. each set of steps that transitions connect, has exactly one INITIAL_STEP
//   (E219; IEC Annex E "zero or more than one initial steps in SFC network");
// - per profile, step names follow the vendor's stricter rule (E218; OpenPCS: a letter first, at
//   most 31 characters);
// - a step's action associations name an action of the chart or the POU, or a BOOL variable
//   (E001/E004);
// - the OpenPCS step macros @ACTIVATE_STEP(S) / @DEACTIVATE_STEP(S) in the chart's IL code name a
//   step of it (E410), and take exactly the step they need (E803).
#pragma once

#include "checker/semantic/body_checker.hpp"

namespace rung::check {

// Checks one sfc_network, the body of `pou` (or a part of a snippet's body).
void check_sfc_network(BodyChecker& body, const ProjectModel& model, const Symbol& pou, SyntaxNode network);

// An @ step macro written as an ST statement: OpenPCS has these macros in IL only (L2658-2670).
void report_step_macro_in_st(BodyChecker& body, SyntaxNode macro);

}  // namespace rung::check
