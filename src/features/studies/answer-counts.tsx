"use client";
// The participants' answers on the Results tab: for each question, how many
// times each answer was recorded in each condition (an answer nobody gave
// shows its zero, so the table reads the same for every condition).
import type { AnswerCounts as Counts } from "@/core/analysis/by-condition";
import { Card } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";

export function AnswerCounts({ answers, noCondition }: { answers: Counts[]; noCondition: string }) {
  if (!answers.length) return null;
  return (
    <>
      <h3 className="font-medium">Answers recorded</h3>
      {answers.map((q) => (
        <Card key={q.question} className="space-y-3 p-4">
          <h4 className="font-medium">{q.question}</h4>
          <Table aria-label={`Answers to “${q.question}” per condition`}>
            <thead>
              <tr>
                <Th>Answer</Th>
                {q.answers[0]!.byCondition.map(({ condition }) => (
                  <Th key={condition ?? noCondition}>{condition ?? noCondition}</Th>
                ))}
              </tr>
            </thead>
            <tbody>
              {q.answers.map(({ answer, byCondition }) => (
                <tr key={answer}>
                  <Td>{answer}</Td>
                  {byCondition.map(({ condition, count }) => (
                    <Td key={condition ?? noCondition}>{count}</Td>
                  ))}
                </tr>
              ))}
            </tbody>
          </Table>
        </Card>
      ))}
    </>
  );
}
