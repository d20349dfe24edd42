// What the panel tests share: the headless ImGui harness (support/imgui_harness.h), and the document tests' short id
// helpers and grid fixture (document/document_test_support.h, in meshedit::document_testing).
#pragma once

#include <functional>

#include <gtest/gtest.h>
#include <imgui.h>

#include "document/document_test_support.h"
#include "support/imgui_harness.h"
#include "ui/element_link.h"
