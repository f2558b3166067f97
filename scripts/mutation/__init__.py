"""The parts of scripts/mutate (docs/testing.md, "Mutation testing")."""
