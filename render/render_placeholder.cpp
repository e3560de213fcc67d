// Placeholder until render/ has sources.
