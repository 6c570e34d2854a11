#include "raylab/film.h"

#include <stdexcept>

namespace raylab {

Film::Film(int width, int height, bool track_variance)
    : width_(width), height_(height), track_variance_(track_variance),
      counts_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0u),
      sums_(counts_.size(), glm::dvec3(0.0)),
      squared_error_(track_variance ? counts_.size() : 0u, glm::dvec3(0.0)) {}

glm::vec3 Film::variance_of_mean_at(int x, int y) const {
  if (!track_variance_) throw std::logic_error("Film::variance_of_mean: this film does not track variance");
  const std::size_t i = index(x, y);
  if (counts_[i] < 2u) return glm::vec3(0.0f);
  const double n = static_cast<double>(counts_[i]);
  return glm::vec3(squared_error_[i] / ((n - 1.0) * n));
}

Image Film::mean() const {
  Image image(width_, height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y) = mean_at(x, y);
  return image;
}

Image Film::variance_of_mean() const {
  if (!track_variance_) throw std::logic_error("Film::variance_of_mean: this film does not track variance");
  Image image(width_, height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y) = variance_of_mean_at(x, y);
  return image;
}

}  // namespace raylab
