#include "window/window_input.h"

#include <GLFW/glfw3.h>
#include <imgui/imgui.h>

namespace vkpt::internal {

InputRecorder::InputRecorder(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window, this);
  previousKey_ = glfwSetKeyCallback(window, OnKey);
  previousButton_ = glfwSetMouseButtonCallback(window, OnButton);
  previousCursor_ = glfwSetCursorPosCallback(window, OnCursor);
  previousScroll_ = glfwSetScrollCallback(window, OnScroll);
  glfwGetCursorPos(window, &cursor_.x, &cursor_.y);
}

InputRecorder::~InputRecorder() {
  glfwSetKeyCallback(window_, previousKey_);
  glfwSetMouseButtonCallback(window_, previousButton_);
  glfwSetCursorPosCallback(window_, previousCursor_);
  glfwSetScrollCallback(window_, previousScroll_);
  glfwSetWindowUserPointer(window_, nullptr);
}

InputRecorder& InputRecorder::Of(GLFWwindow* window) {
  return *static_cast<InputRecorder*>(glfwGetWindowUserPointer(window));
}

WindowInput InputRecorder::Poll(double waitSeconds) {
  if (waitSeconds > 0.0) glfwWaitEventsTimeout(waitSeconds);
  else glfwPollEvents();
  // Held keys fly while held, whether or not the system repeats them.
  const auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0 : 0.0; };
  if (!ImGui::GetIO().WantCaptureKeyboard)
    input_.fly = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                  held(GLFW_KEY_W) - held(GLFW_KEY_S)};
  input_.dragging = button_ >= 0;
  WindowInput taken = input_;
  input_ = WindowInput{};
  return taken;
}

void InputRecorder::OnKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  InputRecorder& r = Of(window);
  if (r.previousKey_) r.previousKey_(window, key, scancode, action, mods);
  if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) r.input_.keys += char('A' + (key - GLFW_KEY_A));
  if (key == GLFW_KEY_ESCAPE) r.input_.keys += '\x1b';
}

void InputRecorder::OnButton(GLFWwindow* window, int button, int action, int mods) {
  InputRecorder& r = Of(window);
  if (r.previousButton_) r.previousButton_(window, button, action, mods);
  if (action == GLFW_PRESS && r.button_ < 0 && !ImGui::GetIO().WantCaptureMouse) {
    r.button_ = button;
    glfwGetCursorPos(window, &r.cursor_.x, &r.cursor_.y);
  } else if (action == GLFW_RELEASE && button == r.button_) {
    r.button_ = -1;
  }
}

void InputRecorder::OnCursor(GLFWwindow* window, double x, double y) {
  InputRecorder& r = Of(window);
  if (r.previousCursor_) r.previousCursor_(window, x, y);
  const glm::dvec2 at(x, y), moved = at - r.cursor_;
  r.cursor_ = at;
  if (r.button_ == GLFW_MOUSE_BUTTON_LEFT) r.input_.orbit += moved;
  else if (r.button_ >= 0) r.input_.pan += moved;
}

void InputRecorder::OnScroll(GLFWwindow* window, double x, double y) {
  InputRecorder& r = Of(window);
  if (r.previousScroll_) r.previousScroll_(window, x, y);
  if (!ImGui::GetIO().WantCaptureMouse) r.input_.wheel += y;
}

}  // namespace vkpt::internal
