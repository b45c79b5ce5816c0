// What a user does in a window, as plain values: drags, the wheel, keys pressed and held,
// gathered from GLFW's callbacks between polls. A viewer maps them onto its camera
// without seeing GLFW. Input over the overlay (Dear ImGui) goes to the overlay alone.
#pragma once

#include <string>

#include <glm/glm.hpp>

struct GLFWwindow;

namespace vkpt::internal {

struct WindowInput {
  glm::dvec2 orbit{0.0};  // cursor motion in pixels (x right, y down) with the left button held
  glm::dvec2 pan{0.0};    // … with the right or middle button held
  double wheel = 0.0;     // clicks, positive turned away from the user (towards the scene)
  std::string keys;       // keys pressed or repeated, in order: 'A'–'Z', '\x1b' for Escape
  glm::dvec3 fly{0.0};    // held: x D − A, y E − Q, z W − S
  bool dragging = false;  // a button is held over the picture
  bool Any() const {
    return orbit != glm::dvec2(0.0) || pan != glm::dvec2(0.0) || wheel != 0.0 || fly != glm::dvec3(0.0);
  }
};

class InputRecorder {
 public:
  // Records `window`'s input; its callbacks call those installed before (the overlay's).
  explicit InputRecorder(GLFWwindow* window);
  ~InputRecorder();  // puts the callbacks before it back
  InputRecorder(const InputRecorder&) = delete;
  InputRecorder& operator=(const InputRecorder&) = delete;

  // Processes the window's events, waiting up to `waitSeconds` for one (0: none), and
  // returns what happened since the last poll.
  WindowInput Poll(double waitSeconds);

 private:
  static InputRecorder& Of(GLFWwindow* window);
  static void OnKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void OnButton(GLFWwindow* window, int button, int action, int mods);
  static void OnCursor(GLFWwindow* window, double x, double y);
  static void OnScroll(GLFWwindow* window, double x, double y);

  GLFWwindow* window_;
  WindowInput input_;
  glm::dvec2 cursor_{0.0};
  int button_ = -1;  // the button dragging (GLFW's number), or −1
  // The callbacks installed before.
  void (*previousKey_)(GLFWwindow*, int, int, int, int) = nullptr;
  void (*previousButton_)(GLFWwindow*, int, int, int) = nullptr;
  void (*previousCursor_)(GLFWwindow*, double, double) = nullptr;
  void (*previousScroll_)(GLFWwindow*, double, double) = nullptr;
};

}  // namespace vkpt::internal
