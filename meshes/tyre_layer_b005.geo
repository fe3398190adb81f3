// Tyred cylinder cover layer of thickness b = 0.05 mm (a = 1 mm: b/a = 0.05), paper §5.4 Fig. 11.
// The strip geometry and its justification are in tyre_layer_strip.inc.
b = 0.05;
// ν = 0.5 layers need contact elements no longer than b (docs/tyre.md): 61 elements, h = 0.85 b.
ne = 61;
Include "tyre_layer_strip.inc";
