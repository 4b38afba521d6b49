// The ray's end and the first absorbing depth in one float, as the Fourier opacity map and the
// power-moment map keep them (FourierEnd, PackFourierEnd and UnpackFourierEnd in
// Core/Shadows/FourierOpacityMap.cxx are the CPU twins); prepended to both techniques' build
// and lookup sources.
//@Dec
// FourierEnd: the box's exit plus one step (1 without a box), rounded up to a float whose 12
// lowest mantissa bits are free.
float seriesEnd(float tEnter, float tExit, float step)
{
  return uintBitsToFloat((floatBitsToUint(tEnter < tExit ? tExit + step : 1.0) | 0xfffu) + 1u);
}

// PackFourierEnd: First as a fraction of End in 4095ths, rounded down.
float packSeriesEnd(float end, float first)
{
  return uintBitsToFloat(floatBitsToUint(end) | uint(floor(4095.0 * clamp(first / end, 0.0, 1.0))));
}

// UnpackFourierEnd.
void unpackSeriesEnd(float stored, out float end, out float first)
{
  uint bits = floatBitsToUint(stored);
  end = uintBitsToFloat(bits & ~0xfffu);
  first = float(bits & 0xfffu) / 4095.0 * end;
}
