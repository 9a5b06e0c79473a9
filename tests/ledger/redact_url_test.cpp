// redact_url: what the logs, `lastcut status` and --check-config show of a ledger connection string
// keeps everything but the secrets, in both of libpq's forms (URI and keyword/value).
#include <gtest/gtest.h>

#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {
namespace {

TEST(LedgerUrl, PasswordOfTheUserIsRedacted) {
  EXPECT_EQ(redact_url("postgresql://u:pw@h:5432/db"), "postgresql://u:***@h:5432/db");
  EXPECT_EQ(redact_url("postgres://u:pw@h/db"), "postgres://u:***@h/db");
  EXPECT_EQ(redact_url("postgresql://u:p:w@h1:5432,h2:5433/db"), "postgresql://u:***@h1:5432,h2:5433/db");
  EXPECT_EQ(redact_url("postgresql://u@h/db"), "postgresql://u@h/db");
  EXPECT_EQ(redact_url("postgresql://h:5432/db"), "postgresql://h:5432/db");
  // An '@' after the authority is no user part: the port stays.
  EXPECT_EQ(redact_url("postgresql://h:5432/db?application_name=a@b"), "postgresql://h:5432/db?application_name=a@b");
}

TEST(LedgerUrl, PasswordInTheQueryIsRedacted) {
  EXPECT_EQ(redact_url("postgresql://u@h/db?password=secret"), "postgresql://u@h/db?password=***");
  EXPECT_EQ(redact_url("postgresql://h/db?sslmode=require&password=secret&connect_timeout=5"),
            "postgresql://h/db?sslmode=require&password=***&connect_timeout=5");
  EXPECT_EQ(redact_url("postgresql:///db?host=/run/postgresql&sslpassword=k3y#x"),
            "postgresql:///db?host=/run/postgresql&sslpassword=***#x");
  EXPECT_EQ(redact_url("postgresql://u:a@h/db?password=b&password=c"), "postgresql://u:***@h/db?password=***&password=***");
  EXPECT_EQ(redact_url("postgresql://h/db?password="), "postgresql://h/db?password=***");
  // Only the keys themselves: a parameter merely ending in "password" is shown.
  EXPECT_EQ(redact_url("postgresql://h/db?mypassword=x"), "postgresql://h/db?mypassword=x");
}

TEST(LedgerUrl, PasswordInAKeywordValueStringIsRedacted) {
  EXPECT_EQ(redact_url("host=h password=secret dbname=lastcut"), "host=h password=*** dbname=lastcut");
  EXPECT_EQ(redact_url("host=h password = secret port=5432"), "host=h password = *** port=5432");
  EXPECT_EQ(redact_url("password='two words \\' and more' user=u"), "password=*** user=u");
  EXPECT_EQ(redact_url("sslpassword=k3y host=h"), "sslpassword=*** host=h");
  EXPECT_EQ(redact_url("host=h user=u "), "host=h user=u ");
}

TEST(LedgerUrl, AKeywordStringItCannotReadHidesTheRest) {
  // An unterminated quote or a word without '=' (libpq refuses both): nothing after it is shown.
  EXPECT_EQ(redact_url("host=h password='secret"), "host=h password=***");
  EXPECT_EQ(redact_url("host=h oops password=secret"), "host=h ***");
  EXPECT_EQ(redact_url("mqtt://u:secret@h"), "***");
}

}  // namespace
}  // namespace lastcut::ledger
