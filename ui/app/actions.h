#pragma once
// The operations on the document, shared by the panels and the script runner so that a
// script does exactly what a click does. Each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.
//
// One header and one source file per feature (ui/README.md, "The viewer's features"):
// this header includes them all.

#include "ui/app/analysis_actions.h"
#include "ui/app/clip_actions.h"
#include "ui/app/document_actions.h"
#include "ui/app/export_actions.h"
#include "ui/app/load_actions.h"
#include "ui/app/notice_actions.h"
#include "ui/app/stage_actions.h"
#include "ui/app/teaching_actions.h"
#include "ui/app/video_actions.h"
