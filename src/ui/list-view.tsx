// A list read from the server, as every list page shows one: a spinner while
// it loads, the problem if it (or an action on it) failed, the empty state
// when there is nothing yet, and otherwise a table with a row per item.
import type { ReactNode } from "react";
import { Problem } from "./problem";
import { Spinner } from "./surface";
import { Table } from "./table";

interface ListQuery<T> {
  isPending: boolean;
  error: unknown;
  data?: T[];
}

export function ListView<T>({
  query,
  problem,
  empty,
  label,
  columns,
  row,
}: {
  query: ListQuery<T>;
  /** An action's error on the list's rows, shown where the list's own would be. */
  problem?: unknown;
  empty?: ReactNode;
  /** The table's accessible name, where the page has more than one. */
  label?: string;
  /** The header cells. */
  columns: ReactNode;
  row: (item: T) => ReactNode;
}) {
  return (
    <>
      {query.isPending && <Spinner />}
      <Problem error={query.error ?? problem} />
      {query.data?.length === 0 && empty}
      {!!query.data?.length && (
        <Table aria-label={label}>
          <thead>
            <tr>{columns}</tr>
          </thead>
          <tbody>{query.data.map(row)}</tbody>
        </Table>
      )}
    </>
  );
}
