//! Lola's task-space description (thesis Table 4.2) with switchable tasks (5.1).
