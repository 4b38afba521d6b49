#include "Isosurface.h"

#include <algorithm>

namespace deepshadow
{

double IsoCrossings::Next(double scalar)
{
  if (!this->Values)
  {
    return scalar;
  }
  const std::vector<double>& values = *this->Values;
  const long count = static_cast<long>(values.size());
  if (this->Interval < 0)
  {
    this->Interval = static_cast<long>(std::upper_bound(values.begin(), values.end(), scalar) - values.begin());
    return NoCrossing();
  }
  // The interval is [values[Interval - 1], values[Interval]], open to infinity at the ends.
  if (this->Interval > 0 && scalar < values[static_cast<size_t>(this->Interval - 1)])
  {
    return values[static_cast<size_t>(--this->Interval)];
  }
  if (this->Interval < count && scalar > values[static_cast<size_t>(this->Interval)])
  {
    return values[static_cast<size_t>(this->Interval++)];
  }
  return NoCrossing();
}

}
