// The sim layer: virtual slaves built from the model, running on the emulated ESC (esi-sim).
// This translation unit only anchors the layer's library until its first sources land.
namespace esi::sim {}
