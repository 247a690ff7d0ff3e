"""Trials in the console: the queue and its runner, the worker processes that run them, and the purge of
deleted ones."""
