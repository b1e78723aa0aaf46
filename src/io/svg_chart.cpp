// PLACEHOLDER, being written.
