// PLACEHOLDER (issue 17)
