"""One module per command, named like it: the command's texts -> a Result. No click, no
printing: the CLI, batch mode and the Python API all call these."""
