// Feature Hash: the PCG integer hash (Jarzynski and Olano 2020) of deepshadow::PcgHash in
// Core/Jitter.h, for reproducible random numbers (jitter, stochastic shadow maps).
//@Dec
uint pcgHash(uint value)
{
  uint state = value * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
