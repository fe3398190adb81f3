// Tyred cylinder cover layer of thickness b = 0.25 mm (a = 1 mm: b/a = 0.25), paper §5.4 Fig. 11.
// The strip geometry and its justification are in tyre_layer_strip.inc.
b = 0.25;
Include "tyre_layer_strip.inc";
