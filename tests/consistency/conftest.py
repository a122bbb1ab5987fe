"""Consistency tests (batch vs single, statics vs independent recomputation); fixtures come from tests/conftest.py."""
