"""The SPARK operator console server (FastAPI): REST API, live event streams, trial workers."""
