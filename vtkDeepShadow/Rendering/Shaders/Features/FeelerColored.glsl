// Feature FeelerColored: feelers and light rays carry a transmittance per colour channel
// (Feeler's FeelerTransmittance becomes vec3); grey ones keep one float.
//@Dec
#define FEELER_COLORED
