// Placeholder until sim/ has sources.
