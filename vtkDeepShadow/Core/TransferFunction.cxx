#include "Core/TransferFunction.h"

#include "Core/OpticalModel.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

PiecewiseLinear::PiecewiseLinear(std::vector<std::pair<double, double>> nodes, bool clamp)
  : Nodes(std::move(nodes))
  , Clamp(clamp)
{
  std::stable_sort(this->Nodes.begin(), this->Nodes.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
}

void PiecewiseLinear::AddNode(double x, double y)
{
  auto at = std::upper_bound(this->Nodes.begin(), this->Nodes.end(), x,
    [](double value, const auto& node) { return value < node.first; });
  this->Nodes.insert(at, { x, y });
}

double PiecewiseLinear::Evaluate(double x) const
{
  if (this->Nodes.empty())
  {
    return 0.0;
  }
  if (x < this->Nodes.front().first)
  {
    return this->Clamp ? this->Nodes.front().second : 0.0;
  }
  if (x > this->Nodes.back().first)
  {
    return this->Clamp ? this->Nodes.back().second : 0.0;
  }
  // First node with node.x > x; the segment is [it - 1, it].
  auto it = std::upper_bound(this->Nodes.begin(), this->Nodes.end(), x,
    [](double value, const auto& node) { return value < node.first; });
  if (it == this->Nodes.end())
  {
    return this->Nodes.back().second;
  }
  const auto& b = *it;
  const auto& a = *(it - 1);
  double t = (x - a.first) / (b.first - a.first);
  if (!std::isfinite(b.first - a.first))
  {
    // Nodes more than DBL_MAX apart (e.g. at -+1.7e308): the same ratio from halves, exact.
    t = (0.5 * x - 0.5 * a.first) / (0.5 * b.first - 0.5 * a.first);
  }
  return a.second + t * (b.second - a.second);
}

double PiecewiseLinear::MaxOver(double lo, double hi) const
{
  // A piecewise-linear function peaks at an end of the interval or at a node inside it.
  double best = std::max(this->Evaluate(lo), this->Evaluate(hi));
  for (const auto& node : this->Nodes)
  {
    if (node.first >= lo && node.first <= hi)
    {
      best = std::max(best, node.second);
    }
  }
  if (!this->Clamp && !this->Nodes.empty() &&
    (lo < this->Nodes.front().first || hi > this->Nodes.back().first))
  {
    best = std::max(best, 0.0);
  }
  return best;
}

glm::dvec3 TransferFunction::Color(double scalar) const
{
  return { this->Red.Evaluate(scalar), this->Green.Evaluate(scalar), this->Blue.Evaluate(scalar) };
}

TransferFunction TransferFunction::Grey(std::vector<std::pair<double, double>> opacityNodes)
{
  TransferFunction tf;
  tf.Opacity = PiecewiseLinear(std::move(opacityNodes));
  for (PiecewiseLinear* channel : { &tf.Red, &tf.Green, &tf.Blue })
  {
    *channel = PiecewiseLinear({ { tf.Opacity.GetNodes().front().first, 0.0 },
      { tf.Opacity.GetNodes().back().first, 1.0 } });
  }
  return tf;
}

TransferTable TransferTable::Sample(const TransferFunction& function, double rangeMin,
  double rangeMax, int size, double stepLength)
{
  TransferTable table;
  table.RangeMin = rangeMin;
  table.RangeMax = rangeMax > rangeMin ? rangeMax : rangeMin + 1.0;
  table.Size = std::max(size, 2);
  table.RGBA.resize(4 * static_cast<size_t>(table.Size));
  for (int i = 0; i < table.Size; ++i)
  {
    const double scalar =
      table.RangeMin + (table.RangeMax - table.RangeMin) * i / (table.Size - 1.0);
    const glm::dvec3 color = function.Color(scalar);
    const double alpha = CorrectOpacity(
      function.Opacity.Evaluate(scalar), stepLength, function.OpacityUnitDistance);
    float* texel = &table.RGBA[4 * static_cast<size_t>(i)];
    texel[0] = static_cast<float>(color.r);
    texel[1] = static_cast<float>(color.g);
    texel[2] = static_cast<float>(color.b);
    texel[3] = static_cast<float>(alpha);
  }
  return table;
}

glm::dvec2 TransferTable::CoordinateMap() const
{
  // (index + 0.5) / size with index = (s - min) / (max - min) * (size - 1)
  const double scale = (this->Size - 1.0) / (this->RangeMax - this->RangeMin);
  return { scale / this->Size, (0.5 - this->RangeMin * scale) / this->Size };
}

double TransferTable::TextureCoordinate(double scalar) const
{
  const glm::dvec2 map = this->CoordinateMap();
  return scalar * map.x + map.y;
}

glm::dvec4 TransferTable::Lookup(double scalar) const
{
  // GL_LINEAR with clamp-to-edge on texel centres (i + 0.5) / Size.
  const double position = std::clamp(
    this->TextureCoordinate(scalar) * this->Size - 0.5, 0.0, static_cast<double>(this->Size - 1));
  const int i0 = std::min(static_cast<int>(std::floor(position)), this->Size - 1);
  const int i1 = std::min(i0 + 1, this->Size - 1);
  const double t = position - i0;
  glm::dvec4 result;
  for (int c = 0; c < 4; ++c)
  {
    result[c] = (1.0 - t) * this->RGBA[4 * static_cast<size_t>(i0) + c] +
      t * this->RGBA[4 * static_cast<size_t>(i1) + c];
  }
  return result;
}

}
