// Tyred cylinder cover layer of thickness b = 0.5 mm (a = 1 mm: b/a = 0.5), paper §5.4 Fig. 11.
// The strip geometry and its justification are in tyre_layer_strip.inc.
b = 0.5;
Include "tyre_layer_strip.inc";
