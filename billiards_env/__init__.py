"""billiards_env: Gymnasium pool environments on an exact, fast billiards physics engine."""
