"""Physics: pure functions on pint quantities (numpy inside). No click, no rich, no I/O."""
